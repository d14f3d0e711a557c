// Loads the built site (site/) in headless Chromium with software WebGL2, checks that the
// page starts without console errors and draws the box, then drags the band with the mouse
// and checks that the band is drawn while pressed and that the box has moved and turned; the
// HUD is drawn, and the H key hides it.
// Replays across platforms: the page steps a fixed replay (tests/fixtures/cross-platform.jsonl)
// to the hash recorded natively; a game played in the page is saved as a download that the
// native build (NATIVE_BINARY, `simulate --replay FILE --hash`) steps to the page's hash; and
// the fixture opened in the page with the O key plays back to its recorded hash. Then the
// stiff scene (3) with the ghosts (G).
// Screenshots go to site/screens/. Run: node .ci/web/browser-test.mjs [site-dir]
import { chromium } from "playwright-core";
import { PNG } from "pngjs";
import http from "node:http";
import fs from "node:fs";
import path from "node:path";
import { execFileSync } from "node:child_process";

const site = path.resolve(process.argv[2] ?? "site");
const fixture = path.resolve("tests/fixtures/cross-platform.jsonl");
// A replay's recorded hash is on its last line, the end record.
const recordedHash = (text) => JSON.parse(text.trim().split("\n").at(-1)).hash;
const screens = path.join(site, "screens");
fs.mkdirSync(screens, { recursive: true });

const types = { ".html": "text/html", ".js": "text/javascript", ".wasm": "application/wasm", ".png": "image/png" };
const server = http.createServer((request, response) => {
  const file = path.join(site, decodeURIComponent(new URL(request.url, "http://x").pathname));
  const target = file.endsWith("/") ? path.join(file, "index.html") : file;
  if (!target.startsWith(site) || !fs.existsSync(target)) {
    response.writeHead(404).end();
    return;
  }
  // As a static server that serves pre-compressed files does: the .br or .gz beside the file
  // when the browser accepts it. The bytes sent are counted (the download before the first frame).
  const accepted = String(request.headers["accept-encoding"] ?? "");
  const headers = { "content-type": types[path.extname(target)] ?? "application/octet-stream" };
  let served = target;
  for (const [encoding, suffix] of [["br", ".br"], ["gzip", ".gz"]]) {
    if (accepted.includes(encoding) && fs.existsSync(target + suffix)) {
      served = target + suffix;
      headers["content-encoding"] = encoding;
      break;
    }
  }
  transferred += fs.statSync(served).size;
  response.writeHead(200, headers);
  fs.createReadStream(served).pipe(response);
});
let transferred = 0;
await new Promise((resolve) => server.listen(0, "127.0.0.1", resolve));
const url = `http://127.0.0.1:${server.address().port}/`;

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  args: [
    "--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist",
    "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
  ],
});
const failures = [];
const check = (ok, message) => { console.log(`${ok ? "ok  " : "FAIL"} ${message}`); if (!ok) failures.push(message); };

try {
  const width = 960, height = 720;
  const page = await browser.newPage({ viewport: { width, height } });
  const errors = [];
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("pageerror", (e) => { if (!String(e).includes("Using exceptions for control flow")) errors.push(String(e)); });

  const shot = async (name) => {
    const buffer = await page.screenshot({ path: path.join(screens, `${name}.png`) });
    return PNG.sync.read(buffer);
  };
  // The box's fill, sRGB (0.16, 0.42, 0.72), give or take the rasteriser.
  const isBox = (png, i) => Math.abs(png.data[i] - 41) < 30 && Math.abs(png.data[i + 1] - 107) < 30 && Math.abs(png.data[i + 2] - 184) < 30;
  // The band: red turning magenta as it stretches.
  const isBand = (png, i) => png.data[i] > 120 && png.data[i + 1] < 60 && png.data[i + 2] > 30;
  const pixels = (png, test) => {
    const found = [];
    for (let y = 0; y < png.height; y++) for (let x = 0; x < png.width; x++) if (test(png, (y * png.width + x) * 4)) found.push([x, y]);
    return found;
  };
  // Where the page draws the tutorial's 640 x 480 screen (CSS px: x, y, width, height), a world
  // point's place on the page, and the box's area there (a square of 60 world px).
  const sceneOn = (p) => p.evaluate(() => window.rubberBandBox?.scene ?? null);
  const toWindow = (scene, x, y) => [scene[0] + (x + 320) * scene[2] / 640, scene[1] + (240 - y) * scene[3] / 480];
  const boxArea = (scene) => (60 * scene[2] / 640) ** 2;
  // The box's fill inside the scene's rectangle (the panel's lit buttons and the HUD's
  // blue text share its colour), and that over the box's area: under 1 uncovered (its outline
  // and pin lie over the fill, a larger part of a smaller box), less where anything covers it.
  const inScene = (scene) => ([x, y]) => !scene || (x >= scene[0] && x <= scene[0] + scene[2] && y >= scene[1] && y <= scene[1] + scene[3]);
  const boxInScene = (png, scene) => pixels(png, isBox).filter(inScene(scene)).length;
  const fillIn = (png, scene) => boxInScene(png, scene) / boxArea(scene);
  // A scene's scripted pull played with the panel open: in every frame sampled the whole box
  // is in view, under neither the panel nor the HUD (either would hide or darken its fill).
  // Returns the least and the most of the box's area seen (the box starts at the scene's
  // centre, in view): the least must be near the most. The band's pixels over the box count
  // as the box's; the energy graph's thin lines and the box's outline are what else varies.
  const boxAlwaysInView = async (p, snap, name, samples = 12) => {
    let [worst, best] = [Infinity, 0];
    for (let i = 0, tries = 0; i < samples && tries < 3 * samples; i++, tries++) {
      await p.waitForTimeout(200);
      const scene = await sceneOn(p);
      const png = await snap(`pull-${i}`);
      // The scene moved while the frame was taken (a HUD line grew): look again.
      if (!scene || JSON.stringify(scene) !== JSON.stringify(await sceneOn(p))) { i--; continue; }
      // The band crosses the box: its pixels inside the box's bounds count as the box's.
      const box = pixels(png, isBox).filter(inScene(scene));
      const [xs, ys] = [box.map((p) => p[0]), box.map((p) => p[1])];
      const bounds = box.length ? [Math.min(...xs), Math.min(...ys), Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys)] : null;
      const crossing = bounds ? pixels(png, isBand).filter(inScene(bounds)).length : 0;
      const seen = (box.length + crossing) / boxArea(scene);
      [worst, best] = [Math.min(worst, seen), Math.max(best, seen)];
    }
    return { worst, best, ok: best > 0.5 && worst > 0.75 * best, said: `${(100 * worst).toFixed(0)}% to ${(100 * best).toFixed(0)}% of its area seen` };
  };
  // The mean time between the page's animation frames over 2 s (Bevy draws in each).
  const frameMs = (p) => p.evaluate(() => new Promise((resolve) => {
    let frames = 0;
    const t0 = performance.now();
    const tick = () => {
      frames++;
      if (performance.now() - t0 < 2000) requestAnimationFrame(tick);
      else resolve((performance.now() - t0) / frames);
    };
    requestAnimationFrame(tick);
  }));
  // Centre, and how much of its bounding box the box fills (1 square, 0.5 at 45 degrees).
  const boxPose = (png, scene = null) => {
    const p = pixels(png, isBox).filter(inScene(scene));
    if (p.length === 0) return null;
    const xs = p.map((q) => q[0]), ys = p.map((q) => q[1]);
    const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
    return { x: xs.reduce((a, b) => a + b) / p.length, y: ys.reduce((a, b) => a + b) / p.length, fill: p.length / ((x1 - x0 + 1) * (y1 - y0 + 1)) };
  };

  const started = Date.now();
  await page.goto(url);
  let first = null;
  for (let i = 0; i < 600 && !first; i++) {
    // The box, a square of 60 world px, most of it in view where the scene is drawn (fitted
    // to what the panel and the HUD leave free, centred there; the page says where, and the
    // frame is taken where it said so before and after).
    const scene = await sceneOn(page);
    const png = await shot("first-frame");
    const still = JSON.stringify(scene) === JSON.stringify(await sceneOn(page));
    const pose = scene && boxPose(png, scene);
    if (still && pose && fillIn(png, scene) > 0.5) first = { png, pose, scene };
    else await page.waitForTimeout(100);
  }
  const firstFrameMs = Date.now() - started;
  const firstFrameBytes = transferred;
  const middle = first && toWindow(first.scene, 0, 0);
  check(first !== null && Math.hypot(first.pose.x - middle[0], first.pose.y - middle[1]) < 20,
    `the box is drawn at the scene's centre (at ${first && [first.pose.x.toFixed(0), first.pose.y.toFixed(0)]}, the scene's at ${middle?.map((v) => v.toFixed(0))}; first frame after ${firstFrameMs} ms, ${firstFrameBytes} bytes transferred)`);
  // The HUD: light text in the top-left corner. H hides it (and the energy graph), so that
  // the pixel checks below see only the scene.
  const isText = (png, i) => png.data[i] > 200 && png.data[i + 1] > 200 && png.data[i + 2] > 200;
  const hudPixels = (png) => pixels(png, isText).filter(([x, y]) => x < 480 && y < 180).length;
  const hud = first ? hudPixels(first.png) : 0;
  check(hud > 500, `the HUD is drawn (${hud} text pixels top left)`);
  await page.focus("canvas");
  await page.keyboard.press("h");
  await page.waitForTimeout(500);
  const hidden = hudPixels(await shot("hud-hidden"));
  check(hidden < 20, `H hides the HUD (${hidden} text pixels left)`);
  const before = boxPose(await shot("before"));

  // Press well right of and above the box, look while pressed, then drag on.
  await page.mouse.move(width / 2 + 330, height / 2 - 250);
  await page.mouse.down();
  await page.mouse.move(width / 2 + 320, height / 2 - 240);
  const pressed = await shot("pressed");
  for (let i = 1; i <= 10; i++) {
    await page.mouse.move(width / 2 + 320 - 20 * i, height / 2 - 240 + 10 * i);
    await page.waitForTimeout(50);
  }
  const band = pixels(pressed, isBand).length;
  check(band > 30, `the band is drawn while pressed (${band} band pixels)`);
  await page.mouse.up();
  // A turning square lines up with the axes now and then: look several times.
  const poses = [];
  for (let i = 0; i < 6; i++) {
    await page.waitForTimeout(250);
    poses.push(boxPose(await shot(`released-${i}`)));
  }
  const after = poses.filter(Boolean).reduce((a, b) => (b.fill < a.fill ? b : a), { fill: 2 });
  await page.waitForTimeout(500);
  const afterBand = pixels(await shot("later"), isBand).length;
  check(afterBand < 5, `the band is gone after release (${afterBand} band pixels)`);

  const last = poses.filter(Boolean).at(-1);
  const moved = before && last ? Math.hypot(last.x - before.x, last.y - before.y) : 0;
  check(moved > 20, `the box moved (${moved.toFixed(1)} px)`);
  check(before && before.fill > 0.95 && after.fill < 0.95,
    `the box turned (fills ${before?.fill.toFixed(2)} of its bounding box, then as little as ${after.fill.toFixed(2)})`);

  // The fixture stepped inside the page, with the core compiled to wasm.
  const fixtureText = fs.readFileSync(fixture, "utf8");
  const nativeHash = recordedHash(fixtureText);
  const inPage = await page.evaluate((text) => window.rubberBandBox?.replayHash(text), fixtureText);
  check(inPage === nativeHash, `the fixture replay steps in the page to the native bits (hash ${inPage}, native ${nativeHash})`);

  // A stiffer band, another integrator, a second pull; then S saves the game as a download.
  for (const key of ["]", "]", "i"]) await page.keyboard.press(key);
  await page.mouse.move(width / 2 - 300, height / 2 + 200);
  await page.mouse.down();
  for (let i = 1; i <= 8; i++) {
    await page.mouse.move(width / 2 - 300 + 40 * i, height / 2 + 200 - 30 * i);
    await page.waitForTimeout(40);
  }
  await page.mouse.up();
  await page.waitForTimeout(300);
  const [download] = await Promise.all([page.waitForEvent("download", { timeout: 10000 }), page.keyboard.press("s")]);
  const saved = path.join(screens, "browser-recorded.jsonl");
  await download.saveAs(saved);
  const browserHash = recordedHash(fs.readFileSync(saved, "utf8"));
  const steps = JSON.parse(fs.readFileSync(saved, "utf8").trim().split("\n").at(-1)).steps;
  check(download.suggestedFilename().match(/^replay-\d+\.jsonl$/) && steps > 100,
    `S downloads the game as ${download.suggestedFilename()} (${steps} steps, hash ${browserHash})`);
  const native = process.env.NATIVE_BINARY;
  if (native) {
    let stepped = "";
    try {
      stepped = execFileSync(native, ["simulate", "--replay", saved, "--hash"], { encoding: "utf8" }).trim();
    } catch (error) {
      stepped = `exit ${error.status}: ${String(error.stderr).trim()}`;
    }
    check(stepped === browserHash, `the browser's recording steps natively to the same bits (native ${stepped})`);
  } else {
    check(process.env.CI !== "true", "NATIVE_BINARY is not set: the browser's recording was not stepped natively");
  }

  // O opens a file chooser; the fixture chosen plays back in the page to its recorded bits.
  const [chooser] = await Promise.all([page.waitForEvent("filechooser", { timeout: 10000 }), page.keyboard.press("o")]);
  await chooser.setFiles(fixture);
  await page.waitForTimeout(1500);
  await page.keyboard.press("h");
  await shot("playback");
  const ended = await page.waitForFunction(() => window.rubberBandBox?.playback, null, { timeout: 120000 })
    .then((handle) => handle.jsonValue()).catch(() => null);
  check(ended?.matched === true && ended?.hash === nativeHash,
    `the fixture opened in the page plays back to its recorded bits (${JSON.stringify(ended)})`);
  await shot("playback-over");

  // The lab: 3 loads the stiff scene, G shows the ghosts (each integrator's outline in its
  // colour). Gizmo lines blend dimmer than their colour, so the hue is looked for: rk4's
  // green, which nothing else on screen has.
  const green = (png, i) => png.data[i + 1] > png.data[i] + 40 && png.data[i + 1] > png.data[i + 2] + 40;
  await page.keyboard.press("3");
  await page.waitForTimeout(1000);
  const withoutGhosts = pixels(await shot("stiff-scene"), green).length;
  const plainFrame = await frameMs(page);
  await page.keyboard.press("g");
  await page.waitForTimeout(1500);
  // rk4's outline can lie under the box and the other ghosts in any one frame (it follows the
  // box closely): the most of it seen in three frames 0.4 s apart.
  let rk4 = 0;
  for (const i of [0, 1, 2]) {
    if (i > 0) await page.waitForTimeout(400);
    rk4 = Math.max(rk4, pixels(await shot(i === 0 ? "ghosts" : `ghosts-${i}`), green).length);
  }
  check(rk4 > 50 && withoutGhosts < 5, `G draws the ghosts on the stiff scene (at most ${rk4} pixels of rk4's green in three frames, ${withoutGhosts} before G)`);
  // P plots them: each ghost a point in its colour, with its name, inside the plot's frame at
  // the left of the scene (world x -312..-92, y -105..25).
  const plotScene = await sceneOn(page);
  const [plotLeft, plotTop] = toWindow(plotScene, -312, 25);
  const [plotRight, plotBottom] = toWindow(plotScene, -92, -105);
  const inPlot = (png, i) => {
    const x = (i / 4) % png.width, y = Math.floor(i / 4 / png.width);
    return x >= plotLeft && x <= plotRight && y >= plotTop && y <= plotBottom && green(png, i);
  };
  const beforePlot = pixels(await shot("ghosts-no-plot"), inPlot).length;
  await page.keyboard.press("p");
  await page.waitForTimeout(1500);
  const plotted = pixels(await shot("plot"), inPlot).length;
  check(plotted > 10 && beforePlot < 5, `P plots the ghosts (${plotted} pixels of rk4's green in the plot's frame, ${beforePlot} before P)`);
  // A figure, not a check: the page's frame time with the lab on and off, side by side.
  const labFrame = await frameMs(page);
  console.log(`frame time (stiff scene, software WebGL): ${plainFrame.toFixed(1)} ms without the lab, ${labFrame.toFixed(1)} ms with ghosts, plot and stability line (${(labFrame / plainFrame).toFixed(2)}x)`);
  await page.keyboard.press("p");
  // The panel (bottom right): "controls" unfolds it, a scene button loads that scene (its
  // scripted band is drawn), pause stops the box. The page says where each button lies.
  await page.keyboard.press("g");
  const buttons = () => page.evaluate(() => window.rubberBandBox?.panel ?? {});
  const centre = (r) => [r[0] + r[2] / 2, r[1] + r[3] / 2];
  let places = await buttons();
  check(Boolean(places.controls), `the panel's button is on screen (${JSON.stringify(places.controls)})`);
  if (places.controls) {
    await page.mouse.click(...centre(places.controls));
    await page.waitForTimeout(500);
    places = await buttons();
    await page.mouse.click(...centre(places.tutorial));
    await page.waitForTimeout(600);
    const scripted = pixels(await shot("panel-scene"), isBand).length;
    check(scripted > 30, `the panel's "tutorial" loads the scene: its scripted band is drawn (${scripted} band pixels)`);
    const pull = await boxAlwaysInView(page, (label) => shot(`desktop-${label}`));
    check(pull.ok, `desktop: the tutorial's pull played with the panel open, the box fully in view in every frame sampled (${pull.said})`);
    await page.mouse.click(...centre(places.pause));
    await page.waitForTimeout(400);
    const [a, b] = [boxPose(await shot("panel-paused")), (await page.waitForTimeout(700), boxPose(await shot("panel-paused-later")))];
    const drift = a && b ? Math.hypot(a.x - b.x, a.y - b.y) : Infinity;
    check(drift < 0.5, `the panel's "pause" stops the box (moved ${drift.toFixed(2)} px in 0.7 s)`);
    places = await buttons();
    check(Boolean(places.resume), `the pause button now says "resume"`);
    if (places.resume) await page.mouse.click(...centre(places.resume));
  }

  // The stability line: explicit Euler at the tutorial's k holds (its damping outweighs its
  // growth up to k = 221 at 100 Hz, 530 at the 240 Hz set above); three presses of ] make k
  // 2e4 (and two, if a slow frame swallows one, 2000), past it, and the HUD's stability line
  // turns red (at k = 20 nothing of the HUD is).
  const isWarning = (png, i) => png.data[i] > 200 && png.data[i + 1] > 60 && png.data[i + 1] < 150 && png.data[i + 2] > 30 && png.data[i + 2] < 130;
  const warnings = (png) => pixels(png, isWarning).filter(([x, y]) => x < 900 && y < 240).length;
  // One key a frame or so: two presses within one frame count once.
  const key = async (k) => { await page.keyboard.press(k); await page.waitForTimeout(350); };
  await key("1");
  await key("i");
  await page.waitForTimeout(300);
  const holding = warnings(await shot("stability-holds"));
  for (let i = 0; i < 3; i++) await key("]");
  const past = warnings(await shot("stability-past"));
  check(past > 30 && holding < 5, `the stability line warns before a blow-up (${past} red pixels past euler's limit, ${holding} at k = 20)`);
  for (let i = 0; i < 3; i++) await key("[");
  for (let i = 0; i < 6; i++) await key("i");


  // Phones, held upright and turned (CSS pixels, touch): the
  // HUD, the graph and the folded panel leave the box uncovered; a finger drags it; a tap
  // unfolds the panel, which still leaves the box in view.
  for (const [name, w, h] of [["phone-portrait", 390, 844], ["phone-landscape", 844, 390]]) {
    const context = await browser.newContext({ viewport: { width: w, height: h }, hasTouch: true, isMobile: true, deviceScaleFactor: 1 });
    const phone = await context.newPage();
    phone.on("pageerror", (e) => { if (!String(e).includes("Using exceptions for control flow")) errors.push(String(e)); });
    const snap = async (label) => PNG.sync.read(await phone.screenshot({ path: path.join(screens, `${name}-${label}.png`), scale: "css" }));
    await phone.goto(url);
    // The scene fits the tutorial's 640 x 480 in what the HUD and the panel leave free: the
    // box's side is 60 of those.
    let start = null, scale = 1, previous = null;
    for (let i = 0; i < 300 && !start; i++) {
      // A page still starting may not be captured yet, nor its scene settled where the HUD
      // leaves room (a frame drawn before it may still be on screen): try again.
      const scene = await sceneOn(phone);
      const settled = scene && JSON.stringify(scene) === JSON.stringify(previous);
      previous = scene;
      if (settled) await phone.waitForTimeout(500);
      const png = settled && await snap("start").catch(() => null);
      const pose = png && boxPose(png, scene);
      if (scene) scale = scene[2] / 640;
      if (pose && fillIn(png, scene) > 0.5) start = { pose, seen: fillIn(png, scene) };
      else await phone.waitForTimeout(100);
    }
    check(start !== null, `${name}: the box is in view and uncovered (${(100 * (start?.seen ?? 0)).toFixed(0)}% of its area seen)`);
    if (!start) { await context.close(); continue; }
    const cdp = await context.newCDPSession(phone);
    const touch = (type, x, y) => cdp.send("Input.dispatchTouchEvent", { type, touchPoints: type === "touchEnd" ? [] : [{ x, y }] });
    // To the left, clear of the graph (top right) and the panel (bottom right).
    const [x0, y0] = [start.pose.x - 60 * scale, start.pose.y];
    await touch("touchStart", x0, y0);
    for (let i = 1; i <= 10; i++) {
      await touch("touchMove", x0 - 6 * i, y0);
      await phone.waitForTimeout(40);
    }
    await touch("touchEnd");
    await phone.waitForTimeout(800);
    const after = boxPose(await snap("dragged"), await sceneOn(phone));
    const moved = after ? Math.hypot(after.x - start.pose.x, after.y - start.pose.y) : 0;
    check(moved > 5 * scale, `${name}: a finger drags the box (${moved.toFixed(1)} px)`);
    const places = await phone.evaluate(() => window.rubberBandBox?.panel ?? {});
    if (places.controls) {
      // A fingertip rests a moment (a tap of a few frames, as a hand makes).
      await touch("touchStart", ...centre(places.controls));
      await phone.waitForTimeout(200);
      await touch("touchEnd");
      await phone.waitForTimeout(800);
      // Folded, the body's buttons take no room.
      const open = await phone.evaluate(() => (window.rubberBandBox?.panel?.pause?.[2] ?? 0) > 0);
      check(open, `${name}: a tap unfolds the panel`);
      // The panel must leave the box uncovered.
      const seen = fillIn(await snap("panel-open"), await sceneOn(phone));
      check(seen > 0.85 * start.seen, `${name}: with the panel open the box is uncovered (${(100 * seen).toFixed(0)}% of its area seen, ${(100 * start.seen).toFixed(0)}% at the start)`);
      // The tutorial's scripted pull, the panel open: the box stays in view throughout.
      const tutorial = (await phone.evaluate(() => window.rubberBandBox?.panel ?? {})).tutorial;
      if (tutorial) {
        await touch("touchStart", ...centre(tutorial));
        await phone.waitForTimeout(200);
        await touch("touchEnd");
        const pull = await boxAlwaysInView(phone, snap);
        check(pull.ok, `${name}: the tutorial's pull played with the panel open, the box fully in view in every frame sampled (${pull.said})`);
      } else {
        check(false, `${name}: the panel's "tutorial" is on screen`);
      }
    } else {
      check(false, `${name}: the panel's button is on screen`);
    }
    await context.close();
  }
  check(errors.length === 0, `no console errors${errors.length ? ": " + errors.join(" | ") : ""}`);
  console.log(`first frame (desktop): ${firstFrameMs} ms after navigation, ${firstFrameBytes} bytes transferred`);
} finally {
  await browser.close();
  server.close();
}
process.exit(failures.length === 0 ? 0 : 1);
