// node .ci/web/real-time.mjs SITE (docs/measurements.md#real-time): the site served and loaded
// at 960 x 720 in headless Chromium (SwiftShader), the tutorial's scene with the lab off and on
// (a link: ghosts, plot, vectors, trail; the Stability card opened by its title), alternated,
// two rounds each. Each round: 4 s to settle, then 20 s in which the page's animation frames are
// counted (Bevy runs one update in each) and the simulated time is read from the status line
// at both ends, so the frame time, the fixed steps a frame and the pace (simulated over wall
// time) come from one window. Prints one line a round and the medians.
import { chromium } from "playwright-core";
import path from "node:path";
import { serve } from "./serve.mjs";

const { url: base, server } = await serve(path.resolve(process.argv[2] ?? "site"));
const browser = await chromium.launch({
  executablePath: "/usr/bin/chromium",
  args: ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist",
    "--disable-background-networking", "--disable-component-update", "--disable-sync"],
});
const heaviest = ["heaviest", "?v=1&scene=stiff&k=1e12&rate=4096&time=16&ghosts=on&plot=on&vectors=on&trail=on", 4096];
const modes = process.env.REAL_TIME_HEAVIEST_ONLY ? [heaviest] : [
  ["lab off", "?v=1&scene=tutorial", 100],
  ["lab on", "?v=1&scene=tutorial&ghosts=on&plot=on&vectors=on&trail=on", 100],
  heaviest,
];
// The simulated time the status line says ("... · t 12.3 s ..."), and the frames counted.
const read = (page) => page.evaluate(() => {
  const texts = window.rubberBandBox?.texts ?? [];
  const status = texts.map((t) => t.text).find((t) => / · t [\d.]+ s/.test(t)) ?? "";
  return { t: Number((status.match(/ · t ([\d.]+) s/) ?? [])[1]), status, frames: window.__frames ?? 0 };
});
const results = Object.fromEntries(modes.map(([mode]) => [mode, []]));
try {
  for (let round = 1; round <= 2; round++) {
    for (const [mode, query, rate] of modes) {
      const page = await browser.newPage({ viewport: { width: 960, height: 720 } });
      await page.addInitScript(() => {
        window.__frames = 0;
        const tick = () => { window.__frames++; requestAnimationFrame(tick); };
        requestAnimationFrame(tick);
      });
      await page.goto(base + query);
      await page.waitForFunction(() => window.rubberBandBox?.scene && window.rubberBandBox?.panel?.Stability, null, { timeout: 120000 });
      if (mode !== "lab off") {
        const [x, y, w, h] = await page.evaluate(() => window.rubberBandBox.panel.Stability);
        await page.mouse.move(x + w / 2, y + h / 2);
        await page.waitForTimeout(300);
        await page.mouse.down();
        await page.waitForTimeout(300);
        await page.mouse.up();
      }
      await page.waitForTimeout(4000);
      const a = await read(page);
      const start = Date.now();
      await page.waitForTimeout(20000);
      const b = await read(page);
      const wall = (Date.now() - start) / 1000;
      const frames = b.frames - a.frames;
      const row = {
        ms: (1000 * wall) / frames,
        steps: ((b.t - a.t) * rate) / frames,
        pace: (b.t - a.t) / wall,
      };
      if (mode === "heaviest") {
        // The pause: Space, one frame, then the simulated time must stand still.
        await page.keyboard.press("Space");
        await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
        const paused = await read(page);
        await page.waitForTimeout(2000);
        const later = await read(page);
        row.pause = `paused at t ${paused.t} s, ${later.frames - paused.frames} frames later t ${later.t} s`;
      }
      results[mode].push(row);
      console.log(`${mode}, round ${round}: ${row.ms.toFixed(1)} ms a frame, ${row.steps.toFixed(2)} fixed steps a frame, pace ${row.pace.toFixed(2)} (${frames} frames in ${wall.toFixed(1)} s; status: "${b.status}")${row.pause ? "; " + row.pause : ""}`);
      await page.screenshot({ path: `/tmp/real-time-${mode.replace(" ", "-")}-${round}.png` });
      await page.close();
    }
  }
} finally {
  await browser.close();
  server.close();
}
for (const [mode] of modes) {
  const rows = results[mode];
  console.log(`browser, ${mode}: ${rows.map((r) => r.ms.toFixed(1)).join(" and ")} ms a frame; ${rows.map((r) => r.steps.toFixed(2)).join(" and ")} steps a frame; pace ${rows.map((r) => r.pace.toFixed(2)).join(" and ")}`);
}
process.exit(0);
