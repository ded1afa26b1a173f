// Runs the browser tests against the production build in a real Chromium.
// Finds a browser in this order: $CHROMIUM_PATH, /usr/bin/chromium,
// Playwright's own build; if none and we are root on Debian/Ubuntu, installs
// Debian's `chromium` package; otherwise says in one line how to get one.
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { chromium } from '@playwright/test';

function findBrowser() {
  const candidates = [
    process.env.CHROMIUM_PATH,
    '/usr/bin/chromium',
    safe(() => chromium.executablePath()),
  ];
  return candidates.find((path) => path && existsSync(path)) ?? null;
}

function safe(f) {
  try {
    return f();
  } catch {
    return null;
  }
}

// The handout tests read Chromium's PDFs with poppler's pdftotext, pdfinfo and pdftoppm.
const POPPLER = '/usr/bin/pdftotext';
const root = typeof process.getuid === 'function' && process.getuid() === 0;
const debian = existsSync('/etc/debian_version') && existsSync('/usr/bin/apt-get');
let browser = findBrowser();
const missing = [
  ...(browser ? [] : ['chromium']),
  ...(existsSync(POPPLER) ? [] : ['poppler-utils']),
];
if (missing.length > 0 && root && debian) {
  console.log(`Installing Debian's ${missing.join(' and ')} with apt-get…`);
  const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
  execFileSync('apt-get', ['update', '-qq'], { stdio: 'inherit', env });
  execFileSync('apt-get', ['install', '-y', '-qq', ...missing], { stdio: 'inherit', env });
  browser = findBrowser();
}
if (!existsSync(POPPLER)) {
  console.error(
    'No pdftotext for the handout tests: install poppler-utils (Debian/Ubuntu: sudo apt-get install poppler-utils).',
  );
  process.exit(1);
}
if (!browser) {
  console.error(
    'No Chromium to run the browser tests: install one (Debian/Ubuntu: sudo apt-get install chromium) or set CHROMIUM_PATH to its executable.',
  );
  process.exit(1);
}

const run = (cmd, args, env = process.env) => {
  const result = spawnSync(cmd, args, { stdio: 'inherit', env });
  if (result.status !== 0) process.exit(result.status ?? 1);
};

run('npx', ['vite', 'build', '--logLevel', 'warn']);
const args = process.argv.slice(2);
const env = { ...process.env, CHROMIUM_PATH: browser };
// Playwright repeats only the projects a run names or reaches last: the
// 'browser' project, which 'timing' depends on, ran once under --repeat-each.
// So a repeated run without --project runs each project on its own, in order.
const repeated = args.some((a) => a.startsWith('--repeat-each'));
if (repeated && !args.some((a) => a.startsWith('--project'))) {
  for (const project of ['browser', 'timing'])
    run('npx', ['playwright', 'test', '--project', project, '--no-deps', ...args], env);
} else run('npx', ['playwright', 'test', ...args], env);
