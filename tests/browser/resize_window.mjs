// A session's windows on the control page in Debian's Chromium, resized as a person would:
//   node resize_window.mjs URL
// Spins the mouse wheel over window 0 (two notches up), pinches window 1 with two fingers on a
// touch screen (Chromium's own touch input, through the DevTools protocol) from 80 to 160
// pixels apart, taps window 0 to raise it, then presses Stop. Prints one JSON line of what it
// saw: each window before and after, and the canvas points the wheel and the pinch were about;
// the C++ test (l2wall/tests/control_page_browser_test.cpp) checks it against the run's summary.
import { canvasPointOf, launch, pagePoint, state, stop, until, windowOf } from './session_page.mjs';

const [url] = process.argv.slice(2);
const seen = {};
const browser = await launch();
const changed = (page, before) => until(page, (s) => {
  const w = windowOf(s, before.id);
  return w && (w.width !== before.width || w.x !== before.x);
});

// Two fingers `from` apart about `c` (page pixels), spread to `to` apart, lifted.
async function pinch(page, c, from, to) {
  const cdp = await page.context().newCDPSession(page);
  const fingers = (d) => [{ x: c.x - d / 2, y: c.y, id: 0 }, { x: c.x + d / 2, y: c.y, id: 1 }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: fingers(from) });
  for (let k = 1; k <= 8; ++k) {
    const d = from + ((to - from) * k) / 8;
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: fingers(d) });
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

async function tap(page, p) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Input.dispatchTouchEvent',
                 { type: 'touchStart', touchPoints: [{ x: p.x, y: p.y, id: 0 }] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

try {
  const context = await browser.newContext({ viewport: { width: 1300, height: 1100 },
                                             hasTouch: true });
  const page = await context.newPage();
  page.setDefaultTimeout(60000);
  await page.goto(url);
  await page.waitForFunction(() => document.querySelectorAll('#windows g.window.movable').length > 0);
  const first = await state(page);

  // The wheel, over a part of window 0 that no other window covers.
  seen.wheel_before = windowOf(first, 0);
  const overWindow0 = await pagePoint(page, { x: 200, y: 150 });
  seen.wheel_at = await canvasPointOf(page, overWindow0);
  await page.mouse.move(overWindow0.x, overWindow0.y);
  await page.mouse.wheel(0, -100);
  await page.mouse.wheel(0, -100);
  seen.wheel_after = windowOf(await changed(page, seen.wheel_before), 0);

  // The pinch, about a part of window 1 that no other window covers.
  seen.pinch_before = windowOf(first, 1);
  const overWindow1 = await pagePoint(page, { x: 1110, y: 745 });
  seen.pinch_at = await canvasPointOf(page, overWindow1);
  await pinch(page, overWindow1, 80, 160);
  seen.pinch_after = windowOf(await changed(page, seen.pinch_before), 1);

  // The tap, on window 0 where it is still uncovered.
  await page.waitForFunction(
      (x) => document.querySelector('#windows g.window[data-id="1"] rect')?.getAttribute('x') === String(x),
      seen.pinch_after.x);
  await tap(page, overWindow0);
  seen.front = (await until(page, (s) => s.windows.shown.at(-1).id === 0)).windows.shown.at(-1).id;
  await stop(page);
} finally {
  await browser.close();
}
console.log(JSON.stringify(seen));
