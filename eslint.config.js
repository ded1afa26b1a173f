import js from '@eslint/js';
import tseslint from 'typescript-eslint';
import globals from 'globals';

export default tseslint.config(
  {
    ignores: [
      'dist/**',
      'node_modules/**',
      'test-results/**',
      'playwright-report/**',
      'artifacts/**',
      'reports/**',
      '.dbg/**',
    ],
  },
  js.configs.recommended,
  ...tseslint.configs.recommended,
  {
    languageOptions: { globals: { ...globals.browser, ...globals.node } },
    rules: {
      '@typescript-eslint/no-unused-vars': ['error', { argsIgnorePattern: '^_' }],
      // Data from a URL must never reach the DOM as markup.
      'no-restricted-properties': [
        'error',
        { property: 'innerHTML', message: 'Build DOM nodes instead of innerHTML.' },
        { property: 'outerHTML', message: 'Build DOM nodes instead of outerHTML.' },
      ],
    },
  },
  {
    // A panel is updated on every frame of a drag: a property set to the value
    // it has is still a write (engine.spec's "writes only what changed").
    files: ['src/**/*.ts'],
    ignores: ['src/app/dom.ts', 'src/**/*.test.ts'],
    rules: {
      'no-restricted-syntax': [
        'error',
        {
          selector:
            'AssignmentExpression > MemberExpression.left[property.name=/^(textContent|disabled|hidden|className)$/]',
          message:
            'Write through setText, setDisabled, setHidden or setClass (app/dom): they write only what changed.',
        },
      ],
    },
  },
);
