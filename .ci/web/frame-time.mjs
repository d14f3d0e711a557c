// node .ci/web/frame-time.mjs SITE_A SITE_B (docs/screen.md): each site served, loaded at 960x720 in headless Chromium
// (SwiftShader), the lab on (G, P, V, T keys; the tutorial's pull, key 1), then frames counted
// with requestAnimationFrame over 10 s; A and B alternated twice.
import { chromium } from "playwright-core";
import path from "node:path";
import { serve } from "./serve.mjs";
const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", args: ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist"] });
const sites = process.argv.slice(2);
const urls = [];
for (const s of sites) urls.push((await serve(path.resolve(s))).url);
for (let round = 0; round < 2; round++) {
  for (let i = 0; i < sites.length; i++) {
    const page = await browser.newPage({ viewport: { width: 960, height: 720 } });
    await page.goto(urls[i]);
    await page.waitForFunction(() => window.rubberBandBox?.scene, null, { timeout: 120000 });
    await page.waitForTimeout(3000);
    await page.mouse.click(5, 360);
    for (const k of ["g", "p", "v", "t", "1"]) { await page.keyboard.press(k); await page.waitForTimeout(200); }
    await page.waitForTimeout(3000);
    const ms = await page.evaluate(() => new Promise((resolve) => {
      let n = 0; const start = performance.now();
      const tick = () => { n++; if (performance.now() - start < 10000) requestAnimationFrame(tick); else resolve((performance.now() - start) / n); };
      requestAnimationFrame(tick);
    }));
    console.log(`${sites[i]} round ${round + 1}: ${ms.toFixed(1)} ms a frame (${(1000 / ms).toFixed(1)} fps)`);
    await page.screenshot({ path: `/tmp/frame-time-${path.basename(sites[i])}-${round}.png` });
    await page.close();
  }
}
await browser.close();
process.exit(0);
