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
  // Centre, and how much of its bounding box the box fills (1 square, 0.5 at 45 degrees).
  const boxPose = (png) => {
    const p = pixels(png, isBox);
    if (p.length === 0) return null;
    const xs = p.map((q) => q[0]), ys = p.map((q) => q[1]);
    const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
    return { x: xs.reduce((a, b) => a + b) / p.length, y: ys.reduce((a, b) => a + b) / p.length, fill: p.length / ((x1 - x0 + 1) * (y1 - y0 + 1)) };
  };

  const started = Date.now();
  await page.goto(url);
  let first = null;
  for (let i = 0; i < 600 && !first; i++) {
    const png = await shot("first-frame");
    // The box, a square of 60 world px: at least a 60 px square on this window. Where: the
    // scene is fitted to what the panel leaves free, centred there.
    const pose = boxPose(png);
    if (pose && pixels(png, isBox).length > 3000) first = { png, pose };
    else await page.waitForTimeout(100);
  }
  const firstFrameMs = Date.now() - started;
  const firstFrameBytes = transferred;
  check(first !== null && Math.abs(first.pose.y - height / 2) < 20 && Math.abs(first.pose.x - width / 2) < 70,
    `the box is drawn at the scene's centre (at ${first && [first.pose.x.toFixed(0), first.pose.y.toFixed(0)]}; first frame after ${firstFrameMs} ms, ${firstFrameBytes} bytes transferred)`);
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
  await page.keyboard.press("g");
  await page.waitForTimeout(1500);
  const rk4 = pixels(await shot("ghosts"), green).length;
  check(rk4 > 50 && withoutGhosts < 5, `G draws the ghosts on the stiff scene (${rk4} pixels of rk4's green, ${withoutGhosts} before G)`);
  // P plots them: each ghost a point in its colour, with its name, inside the plot's frame at
  // the left of the scene (world x -312..-92, y -105..25: 1.5 window px a world px here).
  const inPlot = (png, i) => {
    const x = (i / 4) % png.width, y = Math.floor(i / 4 / png.width);
    return x >= 12 && x <= 342 && y >= 322 && y <= 517 && green(png, i);
  };
  const beforePlot = pixels(await shot("ghosts-no-plot"), inPlot).length;
  await page.keyboard.press("p");
  await page.waitForTimeout(1500);
  const plotted = pixels(await shot("plot"), inPlot).length;
  check(plotted > 10 && beforePlot < 5, `P plots the ghosts (${plotted} pixels of rk4's green in the plot's frame, ${beforePlot} before P)`);
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
    await page.waitForTimeout(1000);
    const scripted = pixels(await shot("panel-scene"), isBand).length;
    check(scripted > 30, `the panel's "tutorial" loads the scene: its scripted band is drawn (${scripted} band pixels)`);
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
    // The scene fits the tutorial's 640 x 480 in the viewport: the box's side is 60 of those.
    const scale = Math.min(w / 640, h / 480);
    const expected = (60 * scale) ** 2;
    let start = null;
    for (let i = 0; i < 300 && !start; i++) {
      // A page still starting may not be captured yet: try again.
      const png = await snap("start").catch(() => null);
      const pose = png && boxPose(png);
      if (pose && pixels(png, isBox).length > 0.5 * expected) start = { pose, seen: pixels(png, isBox).length };
      else await phone.waitForTimeout(100);
    }
    check(start && start.seen > 0.9 * expected, `${name}: the box is in view and uncovered (${start?.seen} of ${expected.toFixed(0)} px)`);
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
    const after = boxPose(await snap("dragged"));
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
      const seen = pixels(await snap("panel-open"), isBox).length;
      check(seen > 0.9 * expected, `${name}: with the panel open the box is uncovered (${seen} of ${expected.toFixed(0)} px)`);
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
