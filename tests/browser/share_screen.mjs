// A screen shared into a session run from the control page in Debian's Chromium:
//   node share_screen.mjs URL
// Chromium's fake screen (--use-fake-device-for-media-stream, picked without a dialog by
// --use-fake-ui-for-media-stream: a dark green picture with a moving shape) is shared with the
// page's "Share a screen" button under the name "tester". The displays are saved before the
// share, while it shows, and after "Stop sharing" closed its window; then the run is stopped.
// Prints one JSON line of what it saw; the C++ test (l2wall/tests/share_screen_browser_test.cpp)
// checks the saved displays' pixels.
import { chromium } from 'playwright-core';
import { state, stop, until } from './session_page.mjs';

const [url] = process.argv.slice(2);
const seen = {};
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--no-sandbox', '--use-fake-ui-for-media-stream', '--use-fake-device-for-media-stream'],
});
// POST /api/save through the page: the folder the run saved the displays to.
const save = (page) => page.evaluate(async () => {
  const res = await fetch(`/api/save${location.search}`, { method: 'POST' });
  return (await res.json()).done;
});
try {
  const page = await browser.newPage({ viewport: { width: 1300, height: 1100 } });
  page.setDefaultTimeout(60000);
  await page.goto(url);
  await page.waitForSelector('#share-control:not([hidden])');
  await until(page, (s) => s.frame >= 2);
  seen.before = await save(page);
  seen.slots = (await state(page)).shares.slots;

  await page.fill('#share-name', 'tester');
  await page.click('#share-start');
  // Its window on the displays, and frames of it shown there.
  const sharing = await until(page, (s) => s.shares.shown.length === 1 &&
      s.shares.shown[0].shown >= 5 && s.windows.shown.some((w) => w.source === 'share'));
  seen.share = sharing.shares.shown[0];
  seen.window = sharing.windows.shown.find((w) => w.source === 'share');
  seen.front = sharing.windows.shown.at(-1).id;
  seen.during = await save(page);
  seen.page_says = await page.locator('#shares').textContent();

  await page.click('#share-stop');
  await until(page, (s) => !s.windows.shown.some((w) => w.source === 'share') &&
      s.shares.shown.length === 0);
  seen.after = await save(page);
  seen.stopped_says = await page.locator('#share-state').textContent();
  await stop(page);
} finally {
  await browser.close();
}
console.log(JSON.stringify(seen));
