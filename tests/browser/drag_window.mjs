// A session's windows on the control page in Debian's Chromium, moved as a person would:
//   node drag_window.mjs URL
// Waits for the windows' outlines, drags window 0 right and down with the mouse, double-clicks
// it to raise it, then presses Stop. Prints one JSON line of what it saw; the C++ test
// (l2wall/tests/control_page_browser_test.cpp) checks it against the run's summary.
import { launch, state, stop, until } from './session_page.mjs';

const [url] = process.argv.slice(2);
const seen = {};
const browser = await launch();
try {
  const page = await browser.newPage({ viewport: { width: 1300, height: 1100 } });
  page.setDefaultTimeout(60000);
  await page.goto(url);
  await page.waitForFunction(() => document.querySelectorAll('#windows g.window.movable').length > 0);
  seen.windows = await page.locator('#windows g.window').count();
  seen.labels = await page.locator('#windows g.window text').allTextContents();
  const before = (await state(page)).windows.shown.find((w) => w.id === 0);
  seen.before = before;

  const box = await page.locator('#windows g.window[data-id="0"] rect').boundingBox();
  const from = { x: box.x + 40, y: box.y + 40 };
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(from.x + 50, from.y + 25, { steps: 5 });
  await page.mouse.move(from.x + 100, from.y + 50, { steps: 5 });
  await page.mouse.up();
  await page.waitForFunction(
      () => document.getElementById('events').textContent.includes('window: move 0 '));
  // The displays show it moved once the frame it moved in is on every display.
  const moving = await until(page, (s) => {
    const w = s.windows.shown.find((x) => x.id === 0);
    return w && (w.x !== before.x || w.y !== before.y);
  });
  seen.after = moving.windows.shown.find((w) => w.id === 0);
  // The page draws the outline where the displays show the window.
  await page.waitForFunction(
      (x) => document.querySelector('#windows g.window[data-id="0"] rect')?.getAttribute('x') === String(x),
      seen.after.x);

  const moved = await page.locator('#windows g.window[data-id="0"] rect').boundingBox();
  await page.mouse.dblclick(moved.x + 20, moved.y + 20);
  seen.front = (await until(page, (s) => s.windows.shown.at(-1).id === 0)).windows.shown.at(-1).id;
  await stop(page);
} finally {
  await browser.close();
}
console.log(JSON.stringify(seen));
