// Dev tool: screenshot a page of a running server in the system Chromium.
// node scripts/shot.mjs URL out.png [width] [height] [keys,to,press]
import { chromium } from '@playwright/test';
const [, , url, out, w = '1400', h = '850', extra = ''] = process.argv;
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking'],
});
const page = await browser.newPage({ viewport: { width: +w, height: +h } });
const errors = [];
page.on('console', (m) => {
  if (m.type() === 'error' || m.type() === 'warning') errors.push(m.type() + ': ' + m.text());
});
page.on('pageerror', (e) => errors.push('pageerror: ' + e.message));
await page.goto(url);
await page.waitForTimeout(600);
for (const k of extra.split(',').filter(Boolean)) {
  await page.keyboard.press(k);
  await page.waitForTimeout(200);
}
await page.screenshot({ path: out });
console.log(errors.join('\n') || 'no console errors');
await browser.close();
