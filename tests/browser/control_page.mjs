// The control page in Debian's Chromium, driven as a person would use it:
//   node control_page.mjs URL OUT_DIR [SCREENSHOT.png]
// Loads the page, waits for every display's picture, presses Pause and watches the frame
// number stop, saves the picture the page shows of display 0 (OUT_DIR/page-display-0.png)
// and presses Save and Stop. Prints one JSON line of what it saw; the C++ test
// (l2wall/tests/control_page_browser_test.cpp) checks it against the run's own files.
import { chromium } from 'playwright-core';
import { writeFileSync } from 'node:fs';

const [url, outDir, screenshot] = process.argv.slice(2);
const seen = {};
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--no-sandbox'],  // as root, Chromium's sandbox refuses to start
});
try {
  const page = await browser.newPage({ viewport: { width: 1300, height: 1100 } });
  page.setDefaultTimeout(60000);
  await page.goto(url);
  // Every display's picture loaded at least once.
  await page.waitForFunction(() => {
    const imgs = [...document.querySelectorAll('#wall img')];
    return imgs.length > 0 && imgs.every((i) => i.dataset.version);
  });
  seen.displays = await page.locator('#wall .display').count();
  seen.title = await page.locator('#wall-name').textContent();
  if (screenshot) await page.screenshot({ path: screenshot });

  await page.click('#pause');
  await page.waitForFunction(() => document.getElementById('run-state').textContent === 'paused');
  // The pictures of the paused frame: published when the pause was taken.
  const version = await page.evaluate(async () => {
    const s = await (await fetch(`/api/state${location.search}`)).json();
    return s.pictures_version;
  });
  await page.waitForFunction(
      (v) => [...document.querySelectorAll('#wall img')].every((i) => Number(i.dataset.version) >= v),
      version);
  seen.frame_paused = Number(await page.locator('#frame').textContent());
  await page.waitForTimeout(700);
  seen.frame_later = Number(await page.locator('#frame').textContent());

  const shown = await page.evaluate(async () => {
    const img = document.querySelector('#wall img[data-id="0"]');
    const bytes = new Uint8Array(await (await fetch(img.src)).arrayBuffer());
    let binary = '';
    for (const b of bytes) binary += String.fromCharCode(b);
    return { scale: Number(img.dataset.scale), png: btoa(binary) };
  });
  writeFileSync(`${outDir}/page-display-0.png`, Buffer.from(shown.png, 'base64'));
  seen.scale = shown.scale;

  await page.click('#save');
  await page.waitForFunction(
      () => document.getElementById('events').textContent.includes('saved the displays'));
  await page.click('#stop');
  // The run ends; its last state (or, once it is gone, the page's own word) says so.
  await page.waitForFunction(
      () => /ended|not reachable/.test(document.getElementById('run-state').textContent));
  seen.end = await page.locator('#run-state').textContent();
} finally {
  await browser.close();
}
console.log(JSON.stringify(seen));
