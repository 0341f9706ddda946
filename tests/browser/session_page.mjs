// What the browser scripts on a session run's page share: Debian's Chromium launched, the run's
// state read through the page, and a wait for the state to get somewhere.
import { chromium } from 'playwright-core';

export function launch() {
  return chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--no-sandbox'],  // as root, Chromium's sandbox refuses to start
  });
}

// A state that is no JSON says what came instead (status and body), so that a failure names it
// (once a CI run got an empty body here).
export const state = (page) =>
  page.evaluate(async () => {
    const r = await fetch(`/api/state${location.search}`);
    const text = await r.text();
    try {
      return JSON.parse(text);
    } catch (e) {
      throw new Error(`/api/state answered ${r.status} with ${text.length} bytes: ` +
                      `${JSON.stringify(text.slice(0, 200))}; headers ` +
                      JSON.stringify([...r.headers]));
    }
  });

export const windowOf = (s, id) => s.windows.shown.find((w) => w.id === id);

// The run's state once `done` says so (polled: the run takes a request at its next frame).
export async function until(page, done) {
  for (const end = Date.now() + 60000; Date.now() < end;) {
    const s = await state(page);
    if (done(s)) return s;
    await page.waitForTimeout(50);
  }
  throw new Error('the state never got there');
}

// The page's point (CSS pixels) showing canvas point `c`, as the wall view is drawn now.
export async function pagePoint(page, c) {
  const [box, canvas] = await Promise.all([
    page.locator('#windows').boundingBox(),
    state(page).then((s) => s.wall.canvas),
  ]);
  return { x: Math.round(box.x + (c.x * box.width) / canvas.width),
           y: Math.round(box.y + (c.y * box.height) / canvas.height) };
}

// The canvas point that page point `p` shows.
export async function canvasPointOf(page, p) {
  const [box, canvas] = await Promise.all([
    page.locator('#windows').boundingBox(),
    state(page).then((s) => s.wall.canvas),
  ]);
  return { x: ((p.x - box.x) * canvas.width) / box.width,
           y: ((p.y - box.y) * canvas.height) / box.height };
}

// Stop pressed, and the page's word that the run ended.
export async function stop(page) {
  await page.click('#stop');
  await page.waitForFunction(
      () => /ended|not reachable/.test(document.getElementById('run-state').textContent));
}
