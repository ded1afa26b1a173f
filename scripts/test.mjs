// `npm test`: every check, in order, stopping at the first that fails; then one
// closing line that counts every test run ("Total: N passed, M failed").
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync } from 'node:fs';

const REPORTS = 'reports';
rmSync(REPORTS, { recursive: true, force: true });
mkdirSync(REPORTS, { recursive: true });

const run = (label, command, args, env = process.env) => {
  console.log(`\n▶ ${label}`);
  const result = spawnSync(command, args, { stdio: 'inherit', env });
  return result.status ?? 1;
};

const counts = { unit: null, browser: null };

function readCounts() {
  const unitFile = `${REPORTS}/unit.json`;
  if (existsSync(unitFile)) {
    const report = JSON.parse(readFileSync(unitFile, 'utf8'));
    counts.unit = { passed: report.numPassedTests, failed: report.numFailedTests };
  }
  const browserFile = `${REPORTS}/browser.json`;
  if (existsSync(browserFile)) {
    const { stats } = JSON.parse(readFileSync(browserFile, 'utf8'));
    counts.browser = { passed: stats.expected + stats.flaky, failed: stats.unexpected };
  }
}

function summary(status) {
  readCounts();
  const parts = Object.entries(counts).filter(([, c]) => c !== null);
  console.log('');
  for (const [name, c] of parts)
    console.log(
      `${name === 'unit' ? 'Unit' : 'Browser'} tests: ${c.passed} passed, ${c.failed} failed`,
    );
  const passed = parts.reduce((sum, [, c]) => sum + c.passed, 0);
  const failed =
    parts.reduce((sum, [, c]) => sum + c.failed, 0) +
    (status !== 0 && parts.every(([, c]) => c.failed === 0) ? 1 : 0);
  console.log(`Total: ${passed} passed, ${failed} failed`);
  process.exit(status);
}

const npx = 'npx';

/**
 * The static checks run side by side: each is one thread of work (14 s, 12 s
 * and 14 s alone), and the machine has two cores. Each one's output is printed
 * whole when it ends, under its own heading.
 */
function runTogether(checks) {
  return Promise.all(
    checks.map(
      ([label, command, args]) =>
        new Promise((resolve) => {
          const child = spawn(command, args, { stdio: ['ignore', 'pipe', 'pipe'] });
          let output = '';
          child.stdout.on('data', (chunk) => (output += chunk));
          child.stderr.on('data', (chunk) => (output += chunk));
          child.on('close', (code) => {
            console.log(`\n▶ ${label}`);
            process.stdout.write(output);
            resolve([label, code ?? 1]);
          });
        }),
    ),
  );
}

const checks = [
  ['Type check (tsc)', npx, ['tsc', '--noEmit']],
  ['Lint (eslint)', npx, ['eslint', '.']],
  ['Format check (prettier)', npx, ['prettier', '--check', '.']],
];
const steps = [
  [
    'Unit and property tests (vitest)',
    npx,
    [
      'vitest',
      'run',
      '--reporter=default',
      '--reporter=json',
      `--outputFile.json=${REPORTS}/unit.json`,
    ],
  ],
  ['Browser tests (playwright, production build)', 'node', ['scripts/e2e.mjs']],
];
for (const [label, status] of await runTogether(checks)) {
  if (status !== 0) {
    console.error(`\n✗ ${label} failed.`);
    summary(status);
  }
}
for (const [label, command, args, env] of steps) {
  const status = run(label, command, args, env);
  if (status !== 0) {
    console.error(`\n✗ ${label} failed.`);
    summary(status);
  }
}
summary(0);
