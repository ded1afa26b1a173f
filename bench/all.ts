// `npm run bench`: the maths benchmark, then the browser one, each in its own
// node process (the maths one with --expose-gc). BENCH_ONLY=maths or
// BENCH_ONLY=browser runs one of them.
import { spawnSync } from 'node:child_process';

const PARTS = {
  maths: ['--expose-gc', '--import', 'tsx', 'bench/run.ts'],
  browser: ['--import', 'tsx', 'bench/browser.ts'],
} as const;

type Part = keyof typeof PARTS;

const only = process.env.BENCH_ONLY;
if (only !== undefined && only !== '' && !(only in PARTS)) {
  console.error(`BENCH_ONLY must be one of ${Object.keys(PARTS).join(', ')}, not "${only}".`);
  process.exit(2);
}
const parts = (only ? [only] : Object.keys(PARTS)) as Part[];

let failed = false;
for (const [i, part] of parts.entries()) {
  if (i > 0) console.log('');
  const result = spawnSync(process.execPath, PARTS[part], {
    cwd: new URL('..', import.meta.url),
    stdio: 'inherit',
  });
  if (result.status !== 0) {
    console.error(`The ${part} benchmark did not finish (exit ${result.status ?? result.signal}).`);
    failed = true;
  }
}
process.exitCode = failed ? 1 : 0;
