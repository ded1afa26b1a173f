/**
 * How the tests and the benchmark start Debian's Chromium: what they measure
 * is the app, not browser features a headless test never shows.
 */

/**
 * Playwright's own list of features it turns off (chromiumSwitches.ts in
 * playwright-core 1.x): a second --disable-features replaces the first, so
 * ours repeats it.
 */
const playwrightDisabled = [
  'AvoidUnnecessaryBeforeUnloadCheckSync',
  'DestroyProfileOnBrowserClose',
  'HttpsUpgrades',
  'HttpsFirstBalancedModeAutoEnable',
  'LensOverlay',
  'MediaRouter',
  'PaintHolding',
  'ThirdPartyStoragePartitioning',
  'AvoidCorsURLLoaderRestartOnRedirect',
  'TcpPortRandomizationWin',
  'OptimizationHints',
  'NetworkTimeServiceQuerying',
  'AimEnabled',
  'PreconnectToSearch',
];
/**
 * Chromium 156 builds the address bar's suggestion popup (a web page of its
 * own, chrome://omnibox-popup.top-chrome, in its own renderer) for every new
 * window, which headless tests never show: 0.85 s of CPU for each test's
 * fresh context, more than the lesson page itself (measured: 2.09 s of CPU a
 * context and lesson load, 1.22 s without it).
 */
const unusedBrowserUi = [
  'WebUIOmniboxPopup',
  'WebUIOmniboxAimPopup',
  'WebUIOmniboxFullPopup',
  'PreloadTopChromeWebUI',
];

export const chromiumArgs = [
  '--no-sandbox',
  '--disable-gpu',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  `--disable-features=${[...playwrightDisabled, ...unusedBrowserUi].join(',')}`,
];
