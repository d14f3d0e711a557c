// node .ci/web/first-press.mjs SITE [RUNS] (docs/measurements.md#time-to-the-first-frame): the
// site served from 127.0.0.1 and loaded at 960 x 720 in headless Chromium (SwiftShader), a fresh
// browser a run. From navigation it says when the wasm's download ended (the resource's
// responseEnd, counted apart), when the page first published the box's corners (the first frame
// with the box drawn), and when a press first made a band: from the box's first frame, the mouse
// is pressed 120 px right of the box's centre and held for up to 3 s, again and again, until
// the box's published corners move (a band pulls the box, at rest until then); the frame at
// which they moved is given, and when that press was sent. The page's clock is read in the page,
// so each reading waits on its main thread, as a player's press does.
import { chromium } from "playwright-core";
import path from "node:path";
import { serve } from "./serve.mjs";

const site = path.resolve(process.argv[2] ?? "site");
const runs = Number(process.argv[3] ?? 3);
const { url, server } = await serve(site);
const args = ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist"];
const round = (ms) => Math.round(ms);
for (let run = 1; run <= runs; run++) {
  const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", args });
  const page = await browser.newPage({ viewport: { width: 960, height: 720 } });
  // The page's own clock, from navigation: performance.now() is 0 at its start.
  await page.goto(url, { waitUntil: "commit" });
  const boxed = await page.waitForFunction(
    () => (window.rubberBandBox?.box?.length ? { at: performance.now(), box: window.rubberBandBox.box } : null),
    null, { timeout: 180000, polling: 10 }).then((h) => h.jsonValue());
  const wasm = await page.evaluate(() => {
    const entry = performance.getEntriesByType("resource").find((e) => e.name.endsWith(".wasm"));
    return entry ? { end: entry.responseEnd, bytes: entry.encodedBodySize || entry.transferSize } : null;
  });
  const centre = boxed.box.reduce((s, c) => [s[0] + c[0] / 4, s[1] + c[1] / 4], [0, 0]);
  const start = JSON.stringify(boxed.box);
  // The pointer comes over the scene first, as a player's does before pressing.
  await page.mouse.move(centre[0] + 120, centre[1]);
  // The frame (the page's clock) at which the box first moved under a press, and the press.
  let banded = null, press = null;
  for (let tries = 0; tries < 100 && banded === null; tries++) {
    const at = await page.evaluate(() => performance.now());
    await page.mouse.move(centre[0] + 120, centre[1]);
    await page.mouse.down();
    banded = await page.waitForFunction((start) => JSON.stringify(window.rubberBandBox?.box) !== start ? performance.now() : null,
      start, { timeout: 3000, polling: "raf" }).then((h) => h.jsonValue()).catch(() => null);
    await page.mouse.up();
    if (banded !== null) press = at;
    if (process.env.FIRST_PRESS_DEBUG) console.log(tries, Math.round(at), banded);
  }
  console.log(`run ${run}: wasm downloaded at ${wasm ? round(wasm.end) : "?"} ms (${wasm?.bytes ?? "?"} bytes), ` +
    `box drawn at ${round(boxed.at)} ms, the box moving under a press at ${banded === null ? "never" : round(banded) + " ms"} ` +
    `(that press sent at ${press === null ? "?" : round(press)} ms)`);
  await browser.close();
}
server.close();
process.exit(0);
