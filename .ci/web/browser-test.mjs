// Loads the built site (site/) in headless Chromium with software WebGL2, checks that the
// page starts without console errors and draws the box, then drags the band with the mouse
// and checks that the band is drawn while pressed and that the box has moved and turned; the
// status line is drawn, and the H key hides the dock of instruments.
// Replays across platforms: the page steps a fixed replay (tests/fixtures/cross-platform.jsonl)
// to the hash recorded natively; a game played in the page is saved as a download that the
// native build (NATIVE_BINARY, `simulate --replay FILE --hash`) steps to the page's hash; and
// the fixture opened in the page with the O key plays back to its recorded hash. Then the
// stiff scene (3) with the ghosts (G) and the plot (P), the Controls card's buttons, the
// stability card, learn mode by the mouse and every card open, all on that one page; then
// links, each opened in a fresh page (the keyboard alone tried on one); and phones (touch).
// Past the first frame two browsers run at once, each with its own pages (below).
// The monkey of random input is .ci/web/monkey.mjs.
// The window is divided into regions: a scene column (a status line, the scene's viewport, a
// hint) and a dock of cards, at the side of a wide window, a bottom sheet of a tall one (its
// titles a row of tabs, one card open at a time). The page publishes where each thing lies
// (window.rubberBandBox: panel, scene, viewport, texts, box; CSS px), so the test presses what
// a player presses, waits on what the page says (or on frames drawn) rather than on the clock
// (only a drag's pace and a hold are timed: they are the input), and checks the layout from
// those rectangles: a rectangle does not vary from run to run as a timing or a pixel count
// does, and a check that fails now and then costs a whole session.
// Screenshots go to site/screens/; a line per section says its seconds.
// Run: node .ci/web/browser-test.mjs [site-dir]
import { chromium } from "playwright-core";
import { PNG } from "pngjs";
import http from "node:http";
import fs from "node:fs";
import path from "node:path";
import { execFile } from "node:child_process";
import zlib from "node:zlib";
import { centre, contains, pressPoint } from "./page.mjs";

const site = path.resolve(process.argv[2] ?? "site");
const fixture = path.resolve("tests/fixtures/cross-platform.jsonl");
// A replay's recorded hash is on its last line, the end record.
const recordedHash = (text) => JSON.parse(text.trim().split("\n").at(-1)).hash;
// Steps a saved replay natively (NATIVE_BINARY, `simulate --replay FILE --hash`): its hash, or
// why not. Without blocking: the other track's page is driven meanwhile.
const stepNatively = (file) => new Promise((resolve) => execFile(process.env.NATIVE_BINARY,
  ["simulate", "--replay", file, "--hash"], { encoding: "utf8" },
  (error, stdout, stderr) => resolve(error ? `exit ${error.code}: ${String(stderr).trim()}` : stdout.trim())));
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

const launch = () => chromium.launch({
  executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  args: [
    "--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist",
    "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
  ],
});
const browser = await launch();
// A second browser (below), started once the desktop's first frame is timed.
let secondBrowser = null;
const failures = [];
const check = (ok, message) => { console.log(`${ok ? "ok  " : "FAIL"} ${message}`); if (!ok) failures.push(message); };
// A line per section with its seconds and the time so far, by track (two run at once, below):
// the slow parts show in CI's log.
const began = Date.now();
const laps = (track) => {
  let lapped = Date.now();
  return (section) => {
    const now = Date.now();
    console.log(`time ${track}, ${section}: ${((now - lapped) / 1000).toFixed(1)} s (${((now - began) / 1000).toFixed(1)} s in all)`);
    lapped = now;
  };
};

// --- What the page publishes, and rectangles ([x, y, width, height], CSS px). ---

// The dock's cards, in its order, by their titles.
const CARDS = ["Controls", "Readouts", "Energy", "Ghosts", "Speed against error", "Stability"];
// Everything the page says about its layout at one moment (one read, so one frame's).
const api = (p) => p.evaluate(() => {
  const a = window.rubberBandBox ?? {};
  return {
    panel: a.panel ?? {}, scene: a.scene ?? null, viewport: a.viewport ?? null, texts: a.texts ?? null,
    box: a.box ?? null, width: window.innerWidth, height: window.innerHeight, frame: window.__testFrames ?? 0,
  };
});
// Counts the page's animation frames (Bevy runs one update in each): samples taken in
// different frames are told apart by it.
const countFrames = () => {
  window.__testFrames = 0;
  const tick = () => { window.__testFrames++; requestAnimationFrame(tick); };
  requestAnimationFrame(tick);
};
// Until the page has drawn `n` more frames.
const frames = (p, n = 2) => p.evaluate((n) => new Promise((resolve) => {
  let left = n;
  const tick = () => (--left <= 0 ? resolve() : requestAnimationFrame(tick));
  requestAnimationFrame(tick);
}), n);
// Until a condition on the page holds (true), or the time is up (false).
const until = (p, condition, arg = null, timeout = 10000) =>
  p.waitForFunction(condition, arg, { timeout }).then(() => true, () => false);
// Until a condition on the page holds (true), or `n` frames have been drawn without it (false):
// for what the game does within a frame or two of an input, however slow the frames.
const withinFrames = async (p, condition, arg, n) => {
  for (let i = 0; ; i++) {
    if (await p.evaluate(condition, arg)) return true;
    if (i >= n) return false;
    await frames(p, 1);
  }
};
// Until the buttons and the viewport stand still for a frame: a layout settled after a change.
const settle = async (p, timeout = 5000) => {
  let before = null;
  for (const end = Date.now() + timeout; Date.now() < end;) {
    await frames(p, 2);
    const now = await p.evaluate(() => JSON.stringify([window.rubberBandBox?.panel, window.rubberBandBox?.viewport]));
    if (now === before) return true;
    before = now;
  }
  return false;
};
// What the page says once its layout has stood still for a frame: the viewport, the buttons
// and where each text starts and how tall it is the same in two frames running (a text's width
// goes with its numbers). The page may publish a text's new place a frame before the
// viewport's (a status line wrapped onto a second line when "behind" is added, the viewport
// moved down under it): the two are read from one layout.
const steady = async (p, tries = 10) => {
  const shape = (s) => JSON.stringify([s.viewport, s.panel, (s.texts ?? []).map((t) => [t.rect[0], t.rect[1], t.rect[3]])]);
  let before = await api(p);
  for (let i = 0; i < tries; i++) {
    await frames(p, 1);
    const now = await api(p);
    if (shape(now) === shape(before)) return now;
    before = now;
  }
  return before;
};
// Two rectangles meet when they share more than a sliver (`tolerance` px) each way.
const meet = (a, b, tolerance = 0.5) =>
  Math.min(a[0] + a[2], b[0] + b[2]) - Math.max(a[0], b[0]) > tolerance &&
  Math.min(a[1] + a[3], b[1] + b[3]) - Math.max(a[1], b[1]) > tolerance;
const fmt = (r) => (r ? `[${r.map((v) => (Array.isArray(v) ? fmt(v) : Number(v).toFixed(1))).join(", ")}]` : String(r));
const say = (t) => `"${t.text.length > 48 ? t.text.slice(0, 45) + "..." : t.text}" ${fmt(t.rect)}`;
const wideWindow = (s) => s.width >= s.height;
const titlesShown = (s) => CARDS.filter((title) => s.panel[title]);
// The box's centre on the page: the mean of its corners.
const boxCentre = (s) => s.box?.length ? [0, 1].map((k) => s.box.reduce((sum, c) => sum + c[k], 0) / s.box.length) : null;

// --- Pixels. ---

// The box's fill, sRGB (0.16, 0.42, 0.72), give or take the rasteriser.
const isBox = (png, i) => Math.abs(png.data[i] - 41) < 30 && Math.abs(png.data[i + 1] - 107) < 30 && Math.abs(png.data[i + 2] - 184) < 30;
// The band: red turning magenta as it stretches ([255, 0, its length / 2]: a short band's blue
// is near 0).
const isBand = (png, i) => png.data[i] > 120 && png.data[i + 1] < 60;
// Light text (the status line's).
const isText = (png, i) => png.data[i] > 200 && png.data[i + 1] > 200 && png.data[i + 2] > 200;
// The warning colour of a text (an integrator past its limit).
const isWarning = (png, i) => png.data[i] > 200 && png.data[i + 1] > 60 && png.data[i + 1] < 150 && png.data[i + 2] > 30 && png.data[i + 2] < 130;
// rk4's green, which nothing else in the scene or the plot has. Gizmo lines blend dimmer than
// their colour, so the hue is looked for (green well above red and blue), not the shade.
const green = (png, i) => png.data[i + 1] > 50 && png.data[i + 1] > 1.4 * png.data[i] && png.data[i + 1] > 1.4 * png.data[i + 2];
// The pixels passing `test`, inside `rect` when given (the scene's viewport: the panel's lit
// buttons share the box's blue, the ghosts' table rk4's green).
const pixels = (png, test, rect = null) => {
  const [x0, y0] = rect ? [Math.max(0, Math.floor(rect[0])), Math.max(0, Math.floor(rect[1]))] : [0, 0];
  const [x1, y1] = rect
    ? [Math.min(png.width, Math.ceil(rect[0] + rect[2])), Math.min(png.height, Math.ceil(rect[1] + rect[3]))]
    : [png.width, png.height];
  const found = [];
  for (let y = y0; y < y1; y++) for (let x = x0; x < x1; x++) if (test(png, (y * png.width + x) * 4)) found.push([x, y]);
  return found;
};
// A card's title lit: the card shows (a lit title is blue, a folded one grey). Read at its
// right end, clear of its text.
const litAt = (png, x, y) => {
  if (x < 0 || y < 0 || x >= png.width || y >= png.height) return null;
  const i = (y * png.width + x) * 4;
  return png.data[i + 2] > 130 && png.data[i + 2] > png.data[i] + 60;
};
const litPoint = (r) => [Math.floor(r[0] + r[2] - 5), Math.floor(r[1] + r[3] / 2)];
const litIn = (png, r) => litAt(png, ...litPoint(r));
// A world point's place on the page (the scene is where the page draws the tutorial's
// 640 x 480 screen), a page point's in the world, and the box's area there (a square of 60
// world px).
const toWindow = (scene, x, y) => [scene[0] + (x + 320) * scene[2] / 640, scene[1] + (240 - y) * scene[3] / 480];
const toWorld = (scene, [x, y]) => [(x - scene[0]) * 640 / scene[2] - 320, 240 - (y - scene[1]) * 480 / scene[3]];
const boxArea = (scene) => (60 * scene[2] / 640) ** 2;
// The box's fill seen over its area: under 1 uncovered (its outline and pin lie over the
// fill), less where anything covers it or the viewport cuts it.
const fillIn = (png, s) => pixels(png, isBox, s.viewport).length / boxArea(s.scene);
// Centre, and how much of its bounding box the box fills (1 square, 0.5 at 45 degrees).
const boxPose = (png, rect = null) => {
  const p = pixels(png, isBox, rect);
  if (p.length === 0) return null;
  const xs = p.map((q) => q[0]), ys = p.map((q) => q[1]);
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  return { x: xs.reduce((a, b) => a + b) / p.length, y: ys.reduce((a, b) => a + b) / p.length, fill: p.length / ((x1 - x0 + 1) * (y1 - y0 + 1)) };
};

// --- Pressing: a mouse, or a finger (Chrome's touch events). ---

const mouseOf = (p) => ({
  touch: false,
  down: async (x, y) => { await p.mouse.move(x, y); await p.mouse.down(); },
  move: (x, y) => p.mouse.move(x, y),
  up: () => p.mouse.up(),
  // A click as a hand makes it: over the button a frame or two first (picking presses what the
  // pointer hovered in the frame before: a move and a press in one frame can miss), down for a
  // frame.
  tap: async (x, y) => {
    await p.mouse.move(x, y);
    await frames(p, 2);
    await p.mouse.down();
    await frames(p, 1);
    await p.mouse.up();
  },
});
// Chrome answers a touch once the page has handled it, a frame or two later. A pull's moves
// wait for that answer, each (a hand's pull as slow as the frames, as it has always been: the
// camera's zoom through a pull depends on its pace); a swipe's (`glide`) do not: moves 40 ms
// apart arrive 40 ms apart, those within a frame merged, as Chrome merges a finger's. Down,
// up and a tap wait for what was sent before them.
const fingerOf = (p, cdp) => {
  const send = (type, touchPoints) => cdp.send("Input.dispatchTouchEvent", { type, touchPoints });
  // What was sent and not yet answered (an answer never awaited, the page closed first, is
  // no error).
  let sent = [];
  const later = (type, touchPoints) => { const answer = send(type, touchPoints); answer.catch(() => {}); sent.push(answer); };
  const answered = async () => { await Promise.all(sent); sent = []; };
  return {
    touch: true,
    down: async (x, y) => { await answered(); await send("touchStart", [{ x, y }]); },
    move: async (x, y) => { await answered(); await send("touchMove", [{ x, y }]); },
    glide: async (x, y) => later("touchMove", [{ x, y }]),
    up: async () => { await answered(); await send("touchEnd", []); },
    // A fingertip rests a moment: down till the game has drawn a frame with it, as a hand taps.
    tap: async (x, y) => {
      await answered();
      await send("touchStart", [{ x, y }]);
      await frames(p, 1);
      later("touchEnd", []);
    },
  };
};

// The bottom of the scene column's hint (on a tall window the dock starts below it).
const dockTop = (s) => {
  if (wideWindow(s) || !s.viewport) return 0;
  const bottom = s.viewport[1] + s.viewport[3];
  const hint = (s.texts ?? []).filter((t) => t.rect[1] >= bottom - 1 && t.rect[1] <= bottom + 12);
  return Math.max(bottom + 20, ...hint.map((t) => t.rect[1] + t.rect[3] + 3));
};
// A spot of the dock where a finger may land without pressing a button: a text of a card
// that lies in no button and is no button's label (the page lists one rectangle a label:
// of two buttons named alike, the time's "÷2" and the rate's, one is not listed). For a drag
// by `dy` (positive: the finger moves up), the spot with the most room that way.
const dockSpot = (s, dy = 0) => {
  const v = s.viewport;
  const buttons = Object.values(s.panel);
  const top = dockTop(s);
  const spots = (s.texts ?? []).filter((t) => !Object.hasOwn(s.panel, t.text)).map((t) => centre(t.rect)).filter(([x, y]) =>
    (wideWindow(s) ? x > v[0] + v[2] + 2 : y > top + 2) && y > 10 && y < s.height - 10 &&
    !buttons.some((b) => contains(b, [x, y], 2)));
  return spots.reduce((best, q) => (!best || (dy > 0 ? q[1] > best[1] : q[1] < best[1]) ? q : best), null);
};
// Scrolls the dock by `dy` px (positive: what lies below comes into view): a finger's drag
// from a spot with no button (a finger landing on a button presses it), else the wheel over
// the dock.
const scrollDock = async (p, s, dy, pointer) => {
  const spot = pointer.touch ? dockSpot(s, dy) : null;
  if (spot) {
    const [x, y0] = spot;
    const y1 = Math.max(2, Math.min(s.height - 2, y0 - dy));
    await pointer.down(x, y0);
    // The drag's pace is the input itself (a swipe, 8 moves 40 ms apart).
    for (let i = 1; i <= 8; i++) {
      await pointer.glide(x, y0 + (y1 - y0) * i / 8);
      await p.waitForTimeout(40);
    }
    await frames(p, 1);
    await pointer.up();
    return;
  }
  const v = s.viewport;
  const at = wideWindow(s) ? [(v[0] + v[2] + s.width) / 2, s.height / 2] : [s.width / 2, (dockTop(s) + s.height) / 2];
  await p.mouse.move(...at);
  await p.mouse.wheel(0, dy);
};
// Scrolls the dock until the button shows; where to press it, or null.
const reveal = async (p, label, pointer) => {
  let sign = 1;
  for (let attempt = 0; attempt < 8; attempt++) {
    const s = await api(p);
    const at = pressPoint(s, label);
    const r = s.panel[label];
    if (at || !r || !s.viewport) return at;
    const y = r[1] + r[3] / 2;
    const top = dockTop(s);
    const below = y > (top + s.height) / 2;
    const amount = Math.min(300, Math.max(60, below ? y - (s.height - 60) : top + 60 - y));
    await scrollDock(p, s, sign * (below ? amount : -amount), pointer);
    await frames(p, 3);
    // The dock went the other way (a wheel's sign): turn.
    const moved = (await api(p)).panel[label];
    if (moved && (below ? moved[1] > r[1] + 1 : moved[1] < r[1] - 1)) sign = -sign;
  }
  return null;
};
// Presses a button of the panel (a card's title, a control), scrolling the dock to it first.
const pressButton = async (p, label, pointer) => {
  const at = await reveal(p, label, pointer);
  if (at) await pointer.tap(...at);
  return Boolean(at);
};
// Whether a card's title is lit (its card shows), read on the page; null if not in view (its
// text not shown: a title scrolled past the dock's edge may still lie in the window).
const lit = async (p, title) => {
  const s = await api(p);
  const r = s.panel[title];
  if (!r || !pressPoint(s, title)) return null;
  const [x, y] = litPoint(r);
  if (x < 0 || y < 0 || x + 1 > s.width || y + 1 > s.height) return null;
  const png = PNG.sync.read(await p.screenshot({ clip: { x, y, width: 1, height: 1 }, scale: "css" }));
  return litAt(png, 0, 0);
};
// Opens a card: its title pressed only if it is not lit (a title toggles: a press on an open
// card's folds it), then until the title is lit. Opening a card can move its title out of view
// (the dock keeps its scroll, and a longer card lets it show): the title is scrolled back to.
// `taken` ({ s, png }: what the page said and a screenshot, taken since the test last pressed
// anything of this title's) answers whether the title is lit without another screenshot, if
// the title lies where it lay then.
// Why the latest opening on a page failed, for the message (by page: two run at once).
const openFailures = new WeakMap();
const openFailure = (p) => openFailures.get(p) ?? "";
const openCard = async (p, title, pointer, taken = null) => {
  openFailures.set(p, "");
  if (!(await reveal(p, title, pointer))) {
    openFailures.set(p, `${title}: its title not brought into view (${fmt((await api(p)).panel[title])})`);
    return false;
  }
  const now = taken && await api(p);
  const still = now && pressPoint(now, title) && pressPoint(taken.s, title) &&
    JSON.stringify(now.panel[title]) === JSON.stringify(taken.s.panel[title]) ? litIn(taken.png, now.panel[title]) : null;
  if (still ?? await lit(p, title)) return true;
  if (!(await pressButton(p, title, pointer))) {
    openFailures.set(p, `${title}: its title not in view to press`);
    return false;
  }
  let seen = null;
  // Generous: on a busy machine SwiftShader draws a frame a second or slower (and a drag that
  // scrolls the dock takes several). Looked at once more after the last scroll. A press still
  // unseen 20 frames later (the title in view, not lit; the game opens a card in the frame that
  // takes the press) was lost: pressed once more (seen in one CI run of 2026-11-26, the
  // Controls title on the desktop, with the wasm unchanged; and here about one run in three
  // at 480 x 360, a mouse's press on a title or on "next ▸").
  const start = Date.now();
  const pressedIn = (await api(p)).frame;
  let pressedAgain = false;
  for (const end = start + 30000; ;) {
    // A screenshot waits for a frame drawn after the press.
    seen = await lit(p, title);
    if (seen) return true;
    if (Date.now() >= end) break;
    if (seen === null) {
      await reveal(p, title, pointer);
      await frames(p, 1);
    } else if (!pressedAgain && (await api(p)).frame > pressedIn + 20) {
      pressedAgain = true;
      await pressButton(p, title, pointer);
    }
  }
  openFailures.set(p, `${title}: pressed, its title ${seen === null ? "out of view" : "not lit"} 30 s later (${fmt((await api(p)).panel[title])})`);
  return false;
};

// The layout's rules, read from the texts the page says it shows (a scrolled dock's clipped
// to what shows): a player must be able to read every text and see the whole scene, so no two
// texts meet, none lies on the scene's viewport, every one lies in the window; and the scene
// keeps the largest share of the window.
const checkLayout = (where, s, share) => {
  if (!s.texts || !s.viewport) {
    check(false, `${where}: the page publishes its texts and its viewport (texts ${s.texts ? s.texts.length : s.texts}, viewport ${fmt(s.viewport)})`);
    return;
  }
  const texts = s.texts;
  const pairs = [];
  for (let i = 0; i < texts.length; i++) for (let j = i + 1; j < texts.length; j++) {
    if (meet(texts[i].rect, texts[j].rect)) pairs.push(`${say(texts[i])} and ${say(texts[j])}`);
  }
  check(pairs.length === 0, `${where}: no two of the ${texts.length} texts shown meet (by 0.5 px or more both ways)${pairs.length ? `; ${pairs.length} pairs do: ${pairs.slice(0, 8).join("; ")}` : ""}`);
  const onScene = texts.filter((t) => meet(t.rect, s.viewport));
  check(onScene.length === 0, `${where}: no text lies on the scene's viewport ${fmt(s.viewport)}${onScene.length ? `; ${onScene.length} do: ${onScene.slice(0, 8).map(say).join("; ")}` : ""}`);
  const out = texts.filter((t) => !(t.rect[0] >= -0.5 && t.rect[1] >= -0.5 && t.rect[0] + t.rect[2] <= s.width + 0.5 && t.rect[1] + t.rect[3] <= s.height + 0.5));
  check(out.length === 0, `${where}: every text lies inside the window (${s.width} x ${s.height})${out.length ? `; ${out.length} do not: ${out.slice(0, 8).map(say).join("; ")}` : ""}`);
  const got = (s.viewport[2] * s.viewport[3]) / (s.width * s.height);
  check(got >= share, `${where}: the scene's viewport ${fmt(s.viewport)} takes at least ${share} of the window's ${s.width} x ${s.height} (${got.toFixed(3)})`);
};

// A hand pulls the box (from its centre) to a point and holds it there: to just inside the
// viewport's top-right corner, and over the dock (past the viewport's right edge on a wide
// window, on the bottom sheet on a tall one), where a camera that chased the anchor once
// shrank the world to a dot. In every frame sampled every corner of the box lies in the
// viewport and the box is at least half as large on the page as when the pull began (a
// world shrunk to a dot keeps the box "inside"); after letting go, the same while it swings
// back. Counted on the rectangles the page publishes, in many frames; a sample is counted
// only in a frame the earlier sample did not see and with the viewport where it was at the
// earlier sample (the page places the box with the viewport of the frame before).
const pullAndHold = async (p, where, pointer, snap, target) => {
  const s = await api(p);
  const from = boxCentre(s);
  if (!from || !s.viewport) {
    check(false, `${where}: the page publishes the box's corners and the viewport (box ${fmt(s.box)}, viewport ${fmt(s.viewport)})`);
    return;
  }
  const v = s.viewport;
  const [to, said] = target === "dock"
    ? (wideWindow(s)
      ? [[(v[0] + v[2] + s.width) / 2, v[1] + 100], "over the dock"]
      : [[v[0] + v[2] / 2 + 40, Math.min(s.height - 8, v[1] + v[3] + 40)], "on the bottom sheet"])
    : [[v[0] + v[2] - 40, v[1] + 40], "40 px inside the viewport's top-right corner"];
  const rest = polygonArea(s.box);
  await pointer.down(...from);
  // The hand's pace is the input itself (10 moves 30 ms apart).
  for (let i = 1; i <= 10; i++) {
    await pointer.move(from[0] + (to[0] - from[0]) * i / 10, from[1] + (to[1] - from[1]) * i / 10);
    await p.waitForTimeout(30);
  }
  const outside = [];
  let [counted, skipped, smallest] = [0, 0, Infinity];
  // Held for at least 2 s, then watched for 2 s after the release: the hold's length is the
  // input itself (a camera chasing the anchor shrinks the world over time); a sample a frame.
  const sample = async (least, most) => {
    let last = null;
    const began = Date.now();
    while ((counted < least || Date.now() - began < 2000) && Date.now() - began < most) {
      await frames(p, 1);
      const now = await api(p);
      if (!last) { last = now; continue; }
      const steady = JSON.stringify(now.viewport) === JSON.stringify(last.viewport);
      const fresh = now.frame !== last.frame;
      last = now;
      if (!fresh) continue;
      if (!steady || !now.viewport) { skipped++; continue; }
      counted++;
      const off = (now.box ?? []).filter((c) => !contains(now.viewport, c, 1));
      if (!now.box?.length || off.length) outside.push(`frame ${now.frame}: corners ${fmt(now.box)}, viewport ${fmt(now.viewport)}`);
      if (now.box?.length) smallest = Math.min(smallest, Math.sqrt(polygonArea(now.box) / rest));
    }
  };
  // The picture of the hold is taken while it is sampled.
  await Promise.all([sample(10, 15000), snap(target === "dock" ? "pull-dock" : "pull")]);
  await pointer.up();
  const held = counted;
  await sample(held + 10, 15000);
  check(held >= 10 && counted >= held + 10 && outside.length === 0 && smallest >= 0.5,
    `${where}: a pull from the box's centre ${fmt(from)} held ${said} ${fmt(to)}, then let go: every corner of the box inside the viewport (1 px tolerance) in all ${counted} frames sampled (${held} held; ${skipped} skipped, the viewport moving), the box at least half its size on the page (${smallest.toFixed(2)} of it at the least)${outside.length ? `; outside in ${outside.length}: ${outside.slice(0, 4).join("; ")}` : ""}`);
};

// The box's area on the page: the polygon of its corners (the shoelace formula).
const polygonArea = (corners) => Math.abs(corners.reduce((sum, [x, y], k) => {
  const [nx, ny] = corners[(k + 1) % corners.length];
  return sum + x * ny - nx * y;
}, 0)) / 2;
// Whether a point lies inside a convex polygon (the box's corners, in either turn).
const inPolygon = (corners, [x, y]) => {
  let sign = 0;
  for (let k = 0; k < corners.length; k++) {
    const [ax, ay] = corners[k], [bx, by] = corners[(k + 1) % corners.length];
    const cross = Math.sign((bx - ax) * (y - ay) - (by - ay) * (x - ax));
    if (cross !== 0 && sign !== 0 && cross !== sign) return false;
    if (cross !== 0) sign = cross;
  }
  return true;
};

// A scene's scripted pull played with the Controls card open: in every frame sampled every
// corner of the box lies in the viewport (the rectangles the page publishes), and the box is
// drawn there, under nothing: in the median frame its fill's pixels in the viewport cover
// most of its area on the page, the polygon of the corners the page publishes for the frame
// taken (the camera widens to keep the box in view, so the box's size on screen varies). Its outline lies over the
// fill's edge, and the band's pixels over the box count as the box's.
const boxAlwaysInView = async (p, snap, samples = 12, least = 0.6) => {
  let [worst, best] = [Infinity, 0];
  const fills = [];
  const outside = [];
  let [sampled, skipped] = [0, 0];
  // A frame at a time: a screenshot waits for a new frame, and the next sample for another.
  for (let tries = 0; sampled < samples && tries < 3 * samples; tries++) {
    const a = await api(p);
    const png = await snap(`pull-${sampled}`);
    const b = await api(p);
    // The frame taken lies between the two reads: counted only if the viewport stayed and the
    // box's size on the page (the camera's zoom) changed by under 5% between them (a box that
    // only moved covers as much).
    const [areaA, areaB] = [a, b].map((s) => (s.box?.length ? polygonArea(s.box) : 0));
    const same = areaA > 0 && areaB > 0 && Math.abs(areaA - areaB) < 0.05 * areaA && a.viewport && b.viewport &&
      JSON.stringify(a.viewport) === JSON.stringify(b.viewport);
    if (!same) { skipped++; continue; }
    sampled++;
    for (const s of [a, b]) {
      const off = s.box.filter((c) => !contains(s.viewport, c, 1));
      if (off.length) outside.push(`frame ${s.frame}: corners ${fmt(s.box)}, viewport ${fmt(s.viewport)}`);
    }
    const area = (areaA + areaB) / 2;
    const xs = b.box.map((c) => c[0]), ys = b.box.map((c) => c[1]);
    const bounds = [Math.min(...xs), Math.min(...ys), Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys)];
    const crossing = pixels(png, isBand, bounds).filter((q) => inPolygon(b.box, [q[0] + 0.5, q[1] + 0.5])).length;
    const seen = (pixels(png, isBox, b.viewport).length + crossing) / area;
    [worst, best] = [Math.min(worst, seen), Math.max(best, seen)];
    fills.push(seen);
  }
  // The median frame: on a loaded machine the frame taken can lie outside the two reads (the
  // box then elsewhere than the corners say, the band over it uncounted); a box covered for
  // real is covered in most frames.
  fills.sort((x, y) => x - y);
  const median = fills.length ? fills[Math.floor(fills.length / 2)] : 0;
  return {
    ok: sampled >= samples / 2 && outside.length === 0 && median >= least,
    said: `${sampled} frames, ${skipped} skipped as the camera zoomed while taken; every corner in the viewport${outside.length ? ` but in ${outside.length} frames: ${outside.slice(0, 3).join("; ")}` : ""}; its fill ${(100 * median).toFixed(0)}% of its area on the page in the median frame, ${(100 * worst).toFixed(0)}% to ${(100 * best).toFixed(0)}% in all, the corners' polygon (at least ${100 * least}% wanted in the median)`,
  };
};

// Learn mode (docs/learn.md): the Controls card's "learn" opens the Learn card; every chapter,
// reached by its "next ▸", shows its title ("3 of 8 ...") and an equation of its own with
// numbers in it, with every corner of the box in the viewport; "leave" ends the mode. An
// equation of each chapter, as the card writes it (a line a text):
const FIRST_EQUATIONS = ["ΣF = F_band + F_damp = (", "θ = ", "τ = r × F = r_x·F_y − r_y·F_x = ", "I = m (w² + h²) / 12 = ", "τ = r × F = r_x·F_y − r_y·F_x = ", "F_damp = −b v = −", "1  ω ← e^(−c dt) ω = ", "box: ½mv² + ½Iω² = "];
// The page's focused control (`rubberBandBox.focus`), and its controls' names and values.
const focusOf = (p) => p.evaluate(() => window.rubberBandBox?.focus ?? null);
const controlValue = (p, name) => p.evaluate((name) =>
  (window.rubberBandBox?.controls ?? []).find((c) => c.name === name)?.value ?? null, name);
const listed = (p, name) => p.evaluate((name) => (window.rubberBandBox?.controls ?? []).some((c) => c.name === name), name);
// Tab (or Shift+Tab) until the control named `name` has the focus; false after 60 presses.
const tabTo = async (p, name, back = false) => {
  for (let presses = 0; presses < 60; presses++) {
    const now = await focusOf(p);
    if (now?.name === name) return true;
    await p.keyboard.press(back ? "Shift+Tab" : "Tab");
    await until(p, (before) => JSON.stringify(window.rubberBandBox?.focus ?? null) !== before, JSON.stringify(now), 5000);
  }
  return false;
};
const liveRegion = (p) => p.evaluate(() => document.getElementById("said")?.textContent ?? "");
const keyboardAlone = async (p) => {
  const where = "keyboard alone";
  await p.focus("canvas");
  // A card opened by Enter on its title.
  let opened = await tabTo(p, "Controls");
  if (opened) {
    await p.keyboard.press("Enter");
    opened = await until(p, () => (window.rubberBandBox?.controls ?? []).some((c) => c.name === "band stiffness k"), null, 10000);
  }
  check(opened, `${where}: Tab to the Controls card's title, Enter: the card opens, its sliders listed in the page (focus ${JSON.stringify(await focusOf(p))})`);
  // k by its slider's keys.
  const k = await controlValue(p, "band stiffness k");
  const onK = opened && await tabTo(p, "band stiffness k");
  // Each press once the game has taken the last (two within a frame count once).
  const kNot = (k) => (window.rubberBandBox?.controls ?? []).find((c) => c.name === "band stiffness k")?.value !== k;
  for (const key of onK ? ["ArrowRight", "ArrowRight"] : []) {
    const before = await controlValue(p, "band stiffness k");
    await p.keyboard.press(key);
    await until(p, kNot, before, 10000);
  }
  const kMoved = onK && await until(p, kNot, k, 10000);
  check(kMoved, `${where}: Tab to k's slider, → twice: k ${k} -> ${await controlValue(p, "band stiffness k")}`);
  // Pause and resume (a slider leaves Space to the game), said in the live region.
  await p.keyboard.press("Space");
  const paused = await until(p, () => (document.getElementById("said")?.textContent ?? "").startsWith("Paused."), null, 10000);
  const saidPaused = await liveRegion(p);
  await p.keyboard.press("Space");
  const resumed = await until(p, () => /^The box is/.test(document.getElementById("said")?.textContent ?? ""), null, 10000);
  check(paused && resumed, `${where}: Space pauses and resumes, the live region says so ("${saidPaused}", then "${await liveRegion(p)}")`);
  // The keyboard's band: Esc gives the scene the focus, B grabs, → pulls, B lets go.
  await p.keyboard.press("Escape");
  await until(p, () => window.rubberBandBox?.focus === null, null, 5000);
  const start = boxCentre(await api(p));
  await p.keyboard.press("b");
  // → held until the box has come 20 px right, however fast the frames come: held for less,
  // the cursor can stop beside the grabbed corner and the band pull the box back.
  await p.keyboard.down("ArrowRight");
  const moved = await until(p, (x) => {
    const box = window.rubberBandBox?.box ?? [];
    return box.length > 0 && box.reduce((sum, c) => sum + c[0], 0) / box.length > x + 20;
  }, start?.[0] ?? 0, 15000);
  await p.keyboard.up("ArrowRight");
  const pulling = await until(p, () => (document.getElementById("said")?.textContent ?? "").includes("A band pulls a corner"), null, 15000);
  await p.screenshot({ path: path.join(screens, "keyboard-band.png") });
  await p.keyboard.press("b");
  const letGo = await until(p, () => (document.getElementById("said")?.textContent ?? "").includes("No band."), null, 15000);
  check(start && pulling && moved && letGo, `${where}: B and → pull the box to the right and B lets go (said: band ${pulling}, no band ${letGo}; the box's centre from ${fmt(start)} to ${fmt(boxCentre(await api(p)))})`);
  // The keyboard's pull, saved by S, steps natively to the page's bits: the same rows as a mouse's.
  const [download] = await Promise.all([p.waitForEvent("download", { timeout: 10000 }), p.keyboard.press("s")]);
  const saved = path.join(screens, "keyboard-recorded.jsonl");
  await download.saveAs(saved);
  const pageHash = recordedHash(fs.readFileSync(saved, "utf8"));
  const stepped = process.env.NATIVE_BINARY ? await stepNatively(saved) : "no NATIVE_BINARY";
  check(stepped === pageHash, `${where}: the keyboard's pull saved by S steps natively to the page's bits (page ${pageHash}, native ${stepped})`);
  // The card closed by Enter on its title.
  let closed = await tabTo(p, "Controls");
  if (closed) {
    await p.keyboard.press("Enter");
    closed = await until(p, () => !(window.rubberBandBox?.controls ?? []).some((c) => c.name === "band stiffness k"), null, 10000);
  }
  check(closed, `${where}: Enter on the Controls title again closes the card (its sliders gone from the list)`);
  // Learn mode by L, its chapters by Tab to "next" and Enter.
  await p.keyboard.press("Escape");
  await p.keyboard.press("l");
  const chapters = FIRST_EQUATIONS.length;
  let walked = (await until(p, () => (window.rubberBandBox?.texts ?? []).some((t) => t.text.startsWith("1 of ")), null, 20000)) ? 1 : 0;
  for (let chapter = 2; walked === chapter - 1 && chapter <= chapters; chapter++) {
    if (!(await tabTo(p, "next"))) break;
    await p.keyboard.press("Enter");
    const title = `${chapter} of ${chapters}`;
    if (await until(p, (title) => (window.rubberBandBox?.texts ?? []).some((t) => t.text.startsWith(title)), title, 20000)) walked = chapter;
  }
  check(walked === chapters, `${where}: L, then Tab to "next" and Enter walks learn mode's ${chapters} chapters (reached ${walked})`);
  await p.keyboard.press("Escape");
  await p.keyboard.press("l");
  // Tab leaves the game: Shift+Tab from its first control goes to the page, not round.
  const first = await tabTo(p, "instruments");
  const firstFocus = await focusOf(p);
  if (first) await p.keyboard.press("Shift+Tab");
  await frames(p, 3);
  const left = await p.evaluate(() => document.activeElement?.id !== "bevy");
  check(first && firstFocus?.first === true && left, `${where}: Shift+Tab from the first control (${JSON.stringify(firstFocus)}) leaves the canvas (focus left: ${left})`);
  // Back in from the page, as a page's own Tab order goes: Tab starts at the game's first
  // control; out again by Shift+Tab, and Shift+Tab back in starts at its last.
  await p.keyboard.press("Tab");
  const inFirst = await until(p, () => document.activeElement?.id === "bevy" && window.rubberBandBox?.focus?.first === true, null, 10000);
  const firstAgain = await focusOf(p);
  await p.keyboard.press("Shift+Tab");
  await frames(p, 3);
  const outAgain = await p.evaluate(() => document.activeElement?.id !== "bevy");
  await p.keyboard.press("Shift+Tab");
  const inLast = await until(p, () => document.activeElement?.id === "bevy" && window.rubberBandBox?.focus?.last === true, null, 10000);
  const lastAgain = await focusOf(p);
  check(inFirst && outAgain && inLast,
    `${where}: Tab from the page back into the game starts at its first control (${JSON.stringify(firstAgain)}); out by Shift+Tab (${outAgain}), Shift+Tab back in starts at its last (${JSON.stringify(lastAgain)})`);
  // Out forward from the last control, and Tab back in: the first again, not where it left.
  await p.keyboard.press("Tab");
  await frames(p, 3);
  const outForward = await p.evaluate(() => document.activeElement?.id !== "bevy");
  await p.keyboard.press("Tab");
  const inFirstAgain = await until(p, () => document.activeElement?.id === "bevy" && window.rubberBandBox?.focus?.first === true, null, 10000);
  check(outForward && inFirstAgain,
    `${where}: Tab from the last control leaves the game (${outForward}), and Tab back in starts at its first again (${JSON.stringify(await focusOf(p))})`);
  const listedNames = await p.evaluate(() => [...document.querySelectorAll("#controls li")].map((li) => li.textContent));
  check(listedNames.includes("instruments") && listedNames.includes("Controls"), `${where}: the page lists the controls for a screen reader (${listedNames.join("; ")})`);
  await p.close();
};

const walkChapters = async (p, where, pointer, snap) => {
  const entered = await openCard(p, "Controls", pointer) && await pressButton(p, "learn", pointer);
  const missing = [];
  let [walked, retaps] = [0, 0];
  for (let chapter = 1; entered && chapter <= FIRST_EQUATIONS.length; chapter++) {
    const title = `${chapter} of ${FIRST_EQUATIONS.length}`;
    const titled = await until(p, (title) => (window.rubberBandBox?.texts ?? []).some((t) => t.text.startsWith(title)), title, 20000);
    // The desktop's pictures (docs/learn.md's) of the chapter settled; a phone's while it
    // settles, a picture only.
    if (pointer.touch) await Promise.all([settle(p), snap(`learn-${chapter}`)]);
    else await settle(p);
    const s = await api(p);
    if (!pointer.touch) await snap(`learn-${chapter}`);
    const equation = (s.texts ?? []).find((t) => t.text.includes(FIRST_EQUATIONS[chapter - 1]) && /\d/.test(t.text));
    const off = (s.box ?? []).filter((c) => !s.viewport || !contains(s.viewport, c, 1));
    if (!titled || !equation || !s.box?.length || off.length) {
      missing.push(`chapter ${chapter}: title ${titled ? "shown" : "missing"}, equation ${equation ? "shown" : `"${FIRST_EQUATIONS[chapter - 1]}" missing`}, corners ${fmt(s.box)} in viewport ${fmt(s.viewport)}`);
    } else {
      walked++;
    }
    if (chapter < FIRST_EQUATIONS.length) {
      // As a player would, a tap that did not take is tapped again (at most three times). The
      // game moves on within the frame that takes the tap: one not taken in 20 frames was lost.
      const next = `${chapter + 1} of ${FIRST_EQUATIONS.length}`;
      let moved = false;
      for (let tries = 0; !moved && tries < 3; tries++) {
        if (tries > 0) retaps++;
        if (!(await pressButton(p, "next ▸", pointer))) break;
        moved = await withinFrames(p, (next) => (window.rubberBandBox?.texts ?? []).some((t) => t.text.startsWith(next)), next, 20);
      }
      if (!moved) {
        missing.push(`chapter ${chapter}: "next ▸" pressed three times, no next chapter (${fmt((await api(p)).panel["next ▸"])})`);
        break;
      }
    }
  }
  const left = entered && await pressButton(p, "leave", pointer) &&
    await until(p, () => !window.rubberBandBox?.panel?.["next ▸"], null, 20000);
  check(entered && walked === FIRST_EQUATIONS.length && left,
    `${where}: learn mode walks all ${FIRST_EQUATIONS.length} chapters, each showing its title, an equation of its own with its numbers and the whole box in the viewport (${walked} shown, ${retaps} taps repeated${missing.length ? `; ${missing.join("; ")}` : ""}); "leave" ends it (${left})`);
};

try {
  const width = 960, height = 720;
  // Where the layout is not what is checked, a small window: software rendering's cost goes
  // with the pixels (a frame, and a screenshot, at 480 x 360 take a quarter of one at
  // 960 x 720). The desktop's size for the first frame and the layout with every card open.
  const small = { width: 480, height: 360 };
  const smallSize = `${small.width} x ${small.height}`;
  // The desktop's pages share a context. Every open page draws in every frame: each is closed
  // once done with.
  const desk = await browser.newContext({ viewport: small });
  const errors = [];
  const pageErrors = (p) => p.on("pageerror", (e) => { if (!String(e).includes("Using exceptions for control flow")) errors.push(String(e)); });
  const page = await desk.newPage();
  await page.setViewportSize({ width, height });
  await page.addInitScript(countFrames);
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  pageErrors(page);
  const mouse = mouseOf(page);

  const shot = async (name) => {
    const buffer = await page.screenshot({ path: path.join(screens, `${name}.png`) });
    return PNG.sync.read(buffer);
  };
  // The mean time between the page's animation frames over 1 s (Bevy draws in each).
  const frameMs = (p) => p.evaluate(() => new Promise((resolve) => {
    let frames = 0;
    const t0 = performance.now();
    const tick = () => {
      frames++;
      if (performance.now() - t0 < 1000) requestAnimationFrame(tick);
      else resolve((performance.now() - t0) / frames);
    };
    requestAnimationFrame(tick);
  }));
  // The same layout in two reads: the viewport exactly (the layout's), the scene nearly (the
  // camera eases, and an eased float need not come to rest exactly).
  const near = (a, b, tolerance) => Boolean(a && b && a.length === b.length && a.every((v, k) => Math.abs(v - b[k]) <= tolerance));
  const sameLayout = (a, b) => near(a.scene, b.scene, 0.5) && JSON.stringify(a.viewport) === JSON.stringify(b.viewport);
  // Until the page publishes where the scene and the box lie (its game is running).
  const running = (p) => until(p, () => Boolean(window.rubberBandBox?.box?.length && window.rubberBandBox?.scene && window.rubberBandBox?.viewport), null, 120000);
  // The status line ("euler · k 20 · 240 Hz · time 1× · t 3.2 s"), and what it says.
  const statusLine = async (p) => ((await api(p)).texts ?? []).find((t) => / · k \S+ · /.test(t.text))?.text ?? "";
  const statusK = (line) => Number(line.match(/ · k (\S+) · /)?.[1]);
  const statusIntegrator = (line) => line.split(" · ")[0];
  const statusTime = (line) => Number(line.match(/ · t (\S+) s/)?.[1]);
  // The game's clock (the status line's t), and until it has gone on by `seconds`: a wait for
  // the simulation to move, on what the page says rather than on the wall's clock.
  const clock = (p) => p.evaluate(() => Number(((window.rubberBandBox?.texts ?? [])
    .find((t) => / · k \S+ · /.test(t.text))?.text ?? "").match(/ · t (\S+) s/)?.[1]));
  const simulated = async (p, seconds, timeout = 10000) => until(p, (end) => Number(((window.rubberBandBox?.texts ?? [])
    .find((t) => / · k \S+ · /.test(t.text))?.text ?? "").match(/ · t (\S+) s/)?.[1]) >= end, (await clock(p)) + seconds, timeout);
  // Presses a key once and waits until the status line says what it did (true), or for 5 s.
  const sent = [];
  const pressFor = async (p, k, done, timeout = 5000) => {
    const before = await statusLine(p);
    sent.push(k);
    await p.keyboard.press(k);
    for (const end = Date.now() + timeout; Date.now() < end;) {
      await frames(p, 1);
      if (done(await statusLine(p), before)) return true;
    }
    return false;
  };
  // A scene loaded: its clock starts over.
  const restarted = (now, before) => statusTime(now) < statusTime(before);

  // Phones, held upright and turned (CSS pixels, touch): the box is in view and uncovered; a
  // finger drags it; a tap on the Controls card's title (a tab on a tall window) opens it,
  // which still leaves the box in view, and its "tutorial" plays that scene's pull in view;
  // then the lab (the Controls card's "plot": the ghosts and the plot) with its layout
  // checked, each tab in turn on the upright phone, and a finger's pull out of the frame. The
  // smaller upright phone gets the lab's checks only, to keep the run short (the layout's
  // rules at every size and with every card open are the native layout test's). Each phone
  // in a context of its own, in the browser `on`.
  const phones = async (on, list, lap) => {
    for (const [name, w, h, full] of list) {
      const where = `${name} (${w} x ${h})`;
      const tall = h > w;
      const context = await on.newContext({ viewport: { width: w, height: h }, hasTouch: true, isMobile: true, deviceScaleFactor: 1 });
      const phone = await context.newPage();
      await phone.addInitScript(countFrames);
      pageErrors(phone);
      const snap = async (label) => PNG.sync.read(await phone.screenshot({ path: path.join(screens, `${name}-${label}.png`), scale: "css" }));
      // The box's share seen, once the scene stands still across the frame taken (or as last
      // seen, if it never does).
      const seenNow = async (label) => {
        let seen = 0;
        for (let i = 0; i < 10; i++) {
          const s = await api(phone);
          const png = await snap(label).catch(() => null);
          if (png && s.scene && s.viewport) seen = fillIn(png, s);
          if (png && s.scene && s.viewport && sameLayout(s, await api(phone))) break;
          await frames(phone, 1);
        }
        return seen;
      };
      // The dock shown by the link: a window under half for the scene would start without it.
      await phone.goto(`${url}?dock=on`);
      await running(phone);
      // The scene fits the tutorial's 640 x 480 in the viewport: the box's side is 60 of those.
      let start = null, scale = 1, previous = null;
      for (let i = 0; i < 300 && !start; i++) {
        // A page still starting may not be captured yet, nor its layout settled (a frame drawn
        // before it may still be on screen: two more frames drawn first): try again.
        const s = await api(phone);
        const settled = s.scene && s.viewport && sameLayout(s, previous ?? {});
        previous = s;
        if (settled) await frames(phone, 2);
        const png = settled && await snap("start").catch(() => null);
        const pose = png && boxPose(png, s.viewport);
        if (s.scene) scale = s.scene[2] / 640;
        if (pose && fillIn(png, s) > 0.5) start = { pose, seen: fillIn(png, s) };
        else await frames(phone, 1);
      }
      check(start !== null, `${where}: the box is in view and uncovered (${(100 * (start?.seen ?? 0)).toFixed(0)}% of its area seen)`);
      if (!start) { await context.close(); continue; }
      const finger = fingerOf(phone, await context.newCDPSession(phone));
      if (full) {
        // To the left (a swipe's pace, 10 moves 40 ms apart: the input itself).
        const [x0, y0] = [start.pose.x - 60 * scale, start.pose.y];
        await finger.down(x0, y0);
        for (let i = 1; i <= 10; i++) {
          await finger.glide(x0 - 6 * i, y0);
          await phone.waitForTimeout(40);
        }
        await finger.up();
        // Until the page says the box has gone 5 px (and 2 more), then a frame drawn there.
        const leave = 5 * scale + 2;
        await until(phone, ([x, y, far]) => {
          const box = window.rubberBandBox?.box ?? [];
          const c = [0, 1].map((k) => box.reduce((sum, q) => sum + q[k], 0) / Math.max(1, box.length));
          return box.length > 0 && Math.hypot(c[0] - x, c[1] - y) > far;
        }, [start.pose.x, start.pose.y, leave], 10000);
        await frames(phone, 2);
        const png = await snap("dragged");
        const after = boxPose(png, (await api(phone)).viewport);
        const moved = after ? Math.hypot(after.x - start.pose.x, after.y - start.pose.y) : 0;
        check(moved > 5 * scale, `${where}: a finger drags the box (${moved.toFixed(1)} px)`);
      }
      const titled = Boolean((await api(phone)).panel.Controls);
      const opened = titled && await openCard(phone, "Controls", finger);
      const listed = opened && await until(phone, () => Boolean(window.rubberBandBox?.panel?.pause));
      check(opened && listed, `${where}: a tap on the "Controls" ${tall ? "tab" : "title"} opens its card (title on screen: ${titled}; lit: ${opened}; its "pause" listed: ${listed})`);
      if (!opened) { await context.close(); continue; }
      await settle(phone);
      if (full) {
        // The Controls card must leave the box uncovered.
        const seen = await seenNow("panel-open");
        check(seen > 0.85 * start.seen, `${where}: with the Controls card open the box is uncovered (${(100 * seen).toFixed(0)}% of its area seen, ${(100 * start.seen).toFixed(0)}% at the start)`);
        // The tutorial's scripted pull, the card open: the box stays in view throughout.
        if (await pressButton(phone, "tutorial", finger)) {
          const pull = await boxAlwaysInView(phone, snap);
          check(pull.ok, `${where}: the tutorial's pull played with the Controls card open, the box fully in view in every frame sampled (${pull.said})`);
        } else {
          check(false, `${where}: the Controls card's "tutorial" is on screen (${fmt((await api(phone)).panel.tutorial)})`);
        }
      }
      // The lab: "plot" turns the ghosts and the plot on and opens their cards (on a tall
      // window the plot's alone).
      const plotted = await pressButton(phone, "plot", finger) &&
        await until(phone, () => Boolean(window.rubberBandBox?.panel?.["Speed against error"]));
      const plotShown = plotted && await openCard(phone, "Speed against error", finger);
      check(plotShown, `${where}: the Controls card's "plot" opens the plot's card (plot's title listed: ${plotted}; lit: ${plotShown})`);
      await settle(phone);
      const lab = await steady(phone);
      let taken = { s: lab, png: await snap(tall ? "lab-plot" : "lab") };
      checkLayout(`${where}, the lab on, ${tall ? "the plot's tab open" : "the Controls, Ghosts and plot cards open"}`, lab, 0.4);
      for (const target of ["corner", "dock"]) await pullAndHold(phone, where, finger, (label) => snap(`lab-${label}`), target);
      if (tall && full) {
        // Each tab in turn: its card opens alone, and the layout's rules hold with it.
        for (const title of CARDS.filter((t) => t !== "Speed against error")) {
          const slug = title.toLowerCase().replace(/[^a-z]+/g, "-");
          // Opened (its tab seen lit), the tabs in view (a long card may have scrolled them away).
          const shown = await openCard(phone, title, finger, taken);
          const why = openFailure(phone);
          await settle(phone);
          if (!pressPoint(await api(phone), title)) {
            await reveal(phone, title, finger);
            await settle(phone);
          }
          const s = await steady(phone);
          const png = await snap(`lab-${slug}`);
          taken = { s, png };
          const inView = titlesShown(s).filter((t) => pressPoint(s, t) && litIn(png, s.panel[t]) !== null);
          const litTabs = inView.filter((t) => litIn(png, s.panel[t]));
          // Judged by the tabs once settled and in view: a long card scrolls its own tab away
          // while it opens, so the polling in openCard may not see it lit.
          check(litTabs.length === 1 && litTabs[0] === title, `${where}: a tap on the "${title}" tab shows its card alone (seen lit while opening: ${shown ? "yes" : why}; lit tabs: ${litTabs.join(", ") || "none"} of the ${inView.length} in view)`);
          checkLayout(`${where}, the lab on, the "${title}" tab open`, s, 0.4);
        }
      }
      if (name === "phone-390") await walkChapters(phone, where, finger, (label) => snap(label));
      await context.close();
      lap(where);
    }
  };

  // Links (docs/links.md). The panel's "link" puts the link of what is on screen in the
  // address bar (and window.rubberBandBox.link); that link opened in a fresh page shows the
  // same state, whose own C writes the same link back. A teacher's link with a key the game
  // does not know and a value out of range opens the rest and names both (the hint line says
  // the latest status for a while, the Readouts card keeps it).
  // The fixture in a link's fragment (deflated, base64url, as the game writes it) plays back
  // in the page to its recorded hash.
  // A page of `context` at `address`, in a window of `size`, once its game runs.
  const openLink = async (context, address, size = small) => {
    const p = await context.newPage();
    await p.setViewportSize(size);
    await p.addInitScript(countFrames);
    pageErrors(p);
    await p.goto(address);
    await until(p, () => Boolean(window.rubberBandBox?.panel?.instruments), null, 120000);
    return p;
  };
  // The link a page's share control writes: the key C, or the panel's "link" pressed.
  const shareOf = async (p, press) => {
    await p.evaluate(() => { if (window.rubberBandBox) delete window.rubberBandBox.link; });
    await press();
    await until(p, () => Boolean(window.rubberBandBox?.link), null, 20000);
    return p.evaluate(() => window.rubberBandBox?.link ?? null);
  };
  const byKey = (p) => async () => { await p.focus("canvas"); await p.keyboard.press("c"); };
  // A teacher's link taken in part, then the keyboard alone on its page, in a desktop's
  // context of the browser `on`.
  const teacherAndKeyboard = async (on, lap) => {
    const context = await on.newContext({ viewport: small });
    const teacher = "?integrator=rk4&frobnicate=1&k=1e20&ghosts=on&dock=on";
    const taught = await openLink(context, url + teacher);
    const said = await until(taught, () => (window.rubberBandBox?.texts ?? []).some((t) => t.text.includes("frobnicate")), null, 20000);
    const statusSaid = ((await api(taught)).texts ?? []).find((t) => t.text.includes("not taken"))?.text;
    const taughtBack = await shareOf(taught, byKey(taught));
    await taught.screenshot({ path: path.join(screens, "link-in-part.png") });
    check(said && statusSaid?.includes("k: must be") && taughtBack === `${url}?v=1&integrator=rk4&ghosts=on`,
      `a link taken in part names what it left under the scene ("${statusSaid}") and opens the rest (${taughtBack})`);
    lap("a teacher's link taken in part");
    // The keyboard alone, not one pointer event (docs/accessibility.md), on that page (no
    // pointer has touched it): Tab to a card's title and open it, Tab to k's slider and move
    // it, pause and resume, pull the box with the keyboard's band, close the card, walk learn
    // mode's chapters, and Tab out of the game; what a screen reader hears is read from the
    // page's live region and its list of controls.
    await keyboardAlone(taught);
    await context.close();
    lap("the keyboard alone");
  };

  const lap = laps("browser 1");
  const started = Date.now();
  // The dock shown by the link, as at 480 x 360 it would start hidden (docs/screen.md).
  await page.goto(`${url}?dock=on`);
  await running(page);
  let first = null;
  for (let i = 0; i < 600 && !first; i++) {
    // The box, a square of 60 world px, most of it in view where the scene is drawn (the
    // tutorial's screen fitted to the viewport, centred there; the page says where, and the
    // frame is taken where it said so before and after).
    const s = await api(page);
    const png = await shot("first-frame");
    const still = sameLayout(s, await api(page));
    const pose = still && s.scene && s.viewport && boxPose(png, s.viewport);
    if (pose && fillIn(png, s) > 0.5) first = { png, pose, s };
    else await frames(page, 1);
  }
  const firstFrameMs = Date.now() - started;
  const firstFrameBytes = transferred;
  const middle = first && toWindow(first.s.scene, 0, 0);
  check(first !== null && Math.hypot(first.pose.x - middle[0], first.pose.y - middle[1]) < 20,
    `the box is drawn at the scene's centre (at ${first && [first.pose.x.toFixed(0), first.pose.y.toFixed(0)]}, the scene's at ${middle?.map((v) => v.toFixed(0))}; first frame after ${firstFrameMs} ms, ${firstFrameBytes} bytes transferred)`);
  // The status line: light text above the viewport (the page says where its texts lie; the
  // dock's "instruments" switch stands at its end).
  let status = { count: 0, texts: [] };
  for (let i = 0; i < 10 && first && status.count <= 40; i++) {
    const s = i === 0 ? first.s : await api(page);
    const png = i === 0 ? first.png : await shot("status-line");
    const texts = (s.texts ?? []).filter((t) => s.viewport && t.rect[1] + t.rect[3] <= s.viewport[1] + 0.5 && t.text !== "instruments");
    status = { count: texts.reduce((n, t) => n + pixels(png, isText, t.rect).length, 0), texts };
    if (status.count <= 40) await frames(page, 1);
  }
  check(status.count > 40, `the status line is drawn above the scene (${status.count} light text pixels in ${status.texts.map(say).join(", ") || "no text above the viewport"})`);
  // H hides the dock: the scene takes the window.
  await page.focus("canvas");
  const docked = await api(page);
  await page.keyboard.press("h");
  const hidden = await until(page, () => !window.rubberBandBox?.panel?.Controls);
  await settle(page);
  const undocked = await api(page);
  await shot("dock-hidden");
  const edge = undocked.viewport ? undocked.viewport[0] + undocked.viewport[2] + 0.5 : -Infinity;
  const stray = (undocked.texts ?? []).filter((t) => t.rect[0] + t.rect[2] > edge);
  check(hidden && titlesShown(undocked).length === 0 && stray.length === 0 && undocked.viewport?.[2] > docked.viewport?.[2],
    `H hides the dock: no card's title listed (${titlesShown(undocked).join(", ") || "none"}), no text right of the scene${stray.length ? ` (${stray.slice(0, 4).map(say).join("; ")})` : ""}, the viewport wider (${fmt(docked.viewport)} to ${fmt(undocked.viewport)})`);
  lap("the first frame, the status line, H");
  // From here on two tracks at once, each driving one page at a time in a browser of its own:
  // each browser has its own GPU process, so SwiftShader draws both pages at once on the
  // machine's two cores (in one browser two pages take turns). This one goes on with the
  // desktop's page and its links; the second takes the upright phone and the phone turned.
  // Then each takes what is left, in turn, till none is: the smaller upright phone, and the
  // teacher's link with the keyboard (whichever track is free first: their lengths vary).
  const left = [
    (on, lap) => phones(on, [["phone-360", 360, 740, false]], lap),
    (on, lap) => teacherAndKeyboard(on, lap),
  ];
  const takeWhatIsLeft = async (on, lap) => { for (let next; (next = left.shift());) await next(on, lap); };
  secondBrowser = await launch();
  const secondTrack = (async () => {
    const lap2 = laps("browser 2");
    await phones(secondBrowser, [["phone-390", 390, 844, true], ["phone-landscape", 844, 390, true]], lap2);
    await takeWhatIsLeft(secondBrowser, lap2);
  })().catch((error) => check(false, `the second browser's track: ${error?.stack ?? error}`));
  // The small window from here to the layout with every card open.
  await page.setViewportSize(small);
  await settle(page);
  const view = await api(page);
  const before = boxPose(await shot("before"), view.viewport);

  // Press well right of and above the box (inside the tutorial's screen, placed through the
  // scene the page reports), look while pressed, then drag on toward the box (a hand's pace,
  // 10 moves 50 ms apart: the input itself).
  const pressedAt = (x, y) => toWindow(view.scene, x, y);
  await mouse.down(...pressedAt(250, 185));
  const [from, to] = [pressedAt(242, 178), pressedAt(90, 106)];
  await page.mouse.move(...from);
  const pressed = await shot("pressed");
  for (let i = 1; i <= 10; i++) {
    await page.mouse.move(from[0] + (to[0] - from[0]) * i / 10, from[1] + (to[1] - from[1]) * i / 10);
    await page.waitForTimeout(50);
  }
  const band = pixels(pressed, isBand, view.viewport).length;
  check(band > 30, `the band is drawn while pressed (${band} band pixels)`);
  await page.mouse.up();
  // A turning square lines up with the axes now and then: look several times, 0.2 s of the
  // game's clock apart.
  const poses = [];
  for (let i = 0; i < 6; i++) {
    await simulated(page, 0.2);
    const png = await shot(`released-${i}`);
    poses.push(boxPose(png, (await api(page)).viewport));
  }
  const after = poses.filter(Boolean).reduce((a, b) => (b.fill < a.fill ? b : a), { fill: 2 });
  // The page says the band has gone (its live region), and draws a frame without it.
  await until(page, () => (window.rubberBandBox?.said ?? "").includes("No band."), null, 5000);
  await frames(page, 2);
  const afterBand = pixels(await shot("later"), isBand, (await api(page)).viewport).length;
  check(afterBand < 5, `the band is gone after release (${afterBand} band pixels)`);

  const last = poses.filter(Boolean).at(-1);
  const moved = before && last ? Math.hypot(last.x - before.x, last.y - before.y) : 0;
  check(moved > 20, `the box moved (${moved.toFixed(1)} px)`);
  check(before && before.fill > 0.95 && after.fill < 0.95,
    `the box turned (fills ${before?.fill.toFixed(2)} of its bounding box, then as little as ${after.fill.toFixed(2)})`);
  lap("a pull by the mouse");

  // The fixture stepped inside the page, with the core compiled to wasm.
  const fixtureText = fs.readFileSync(fixture, "utf8");
  const nativeHash = recordedHash(fixtureText);
  const inPage = await page.evaluate((text) => window.rubberBandBox?.replayHash(text), fixtureText);
  check(inPage === nativeHash, `the fixture replay steps in the page to the native bits (hash ${inPage}, native ${nativeHash})`);

  // A stiffer band, another integrator, a second pull (from the lower left toward the
  // centre, 8 moves 40 ms apart); then S saves the game as a download.
  for (const key of ["]", "]", "i"]) await page.keyboard.press(key);
  const second = await api(page);
  const [pullFrom, pullTo] = [toWindow(second.scene, -225, -150), toWindow(second.scene, 15, 30)];
  await mouse.down(...pullFrom);
  for (let i = 1; i <= 8; i++) {
    await page.mouse.move(pullFrom[0] + (pullTo[0] - pullFrom[0]) * i / 8, pullFrom[1] + (pullTo[1] - pullFrom[1]) * i / 8);
    await page.waitForTimeout(40);
  }
  await page.mouse.up();
  // The release read by the game (and recorded) before S.
  await frames(page, 2);
  const [download] = await Promise.all([page.waitForEvent("download", { timeout: 10000 }), page.keyboard.press("s")]);
  const saved = path.join(screens, "browser-recorded.jsonl");
  await download.saveAs(saved);
  const browserHash = recordedHash(fs.readFileSync(saved, "utf8"));
  const steps = JSON.parse(fs.readFileSync(saved, "utf8").trim().split("\n").at(-1)).steps;
  check(download.suggestedFilename().match(/^replay-\d+\.jsonl$/) && steps > 100,
    `S downloads the game as ${download.suggestedFilename()} (${steps} steps, hash ${browserHash})`);
  const native = process.env.NATIVE_BINARY;
  if (native) {
    const stepped = await stepNatively(saved);
    check(stepped === browserHash, `the browser's recording steps natively to the same bits (native ${stepped})`);
  } else {
    check(process.env.CI !== "true", "NATIVE_BINARY is not set: the browser's recording was not stepped natively");
  }

  // O opens a file chooser; the fixture chosen plays back in the page to its recorded bits.
  // H shows the dock again once the page says it plays.
  const [chooser] = await Promise.all([page.waitForEvent("filechooser", { timeout: 10000 }), page.keyboard.press("o")]);
  await chooser.setFiles(fixture);
  const playing = await until(page, () => (window.rubberBandBox?.texts ?? []).some((t) => t.text.startsWith("playing ")), null, 20000);
  await page.keyboard.press("h");
  await shot("playback");
  const ended = await page.waitForFunction(() => window.rubberBandBox?.playback, null, { timeout: 120000 })
    .then((handle) => handle.jsonValue()).catch(() => null);
  check(ended?.matched === true && ended?.hash === nativeHash,
    `the fixture opened in the page plays back to its recorded bits (${JSON.stringify(ended)}; said it plays: ${playing})`);
  await shot("playback-over");
  await until(page, () => Boolean(window.rubberBandBox?.panel?.Controls));
  lap("replays: in the page, natively, opened");

  // The lab: 3 loads the stiff scene, G shows the ghosts (each integrator's outline in its
  // colour) and opens their card. rk4's green is looked for in the viewport only (the ghosts'
  // table has rk4's row in it). At 640 x 480, here and for the Controls card: the plot's card
  // below the ghosts' table needs the height, and the box in a scene beside the open Controls
  // card the width (its fill is judged against its outline).
  const labSize = { width: 640, height: 480 };
  await page.setViewportSize(labSize);
  await settle(page);
  await page.focus("canvas");
  const stiff = await pressFor(page, "3", restarted, 10000);
  await frames(page, 2);
  const withoutGhosts = pixels(await shot("stiff-scene"), green, (await api(page)).viewport).length;
  const plainFrame = await frameMs(page);
  await page.keyboard.press("g");
  await until(page, () => Boolean(window.rubberBandBox?.panel?.Ghosts));
  // The ghosts part from the box as the game's clock runs: a second of it.
  await simulated(page, 1);
  // rk4's outline can lie under the box and the other ghosts in any one frame (it follows the
  // box closely): the most of it seen in three frames 0.4 s of the game's clock apart.
  let rk4 = 0;
  for (const i of [0, 1, 2]) {
    if (i > 0) await simulated(page, 0.4);
    const png = await shot(i === 0 ? "ghosts" : `ghosts-${i}`);
    rk4 = Math.max(rk4, pixels(png, green, (await api(page)).viewport).length);
  }
  check(rk4 > 50 && withoutGhosts < 5, `G draws the ghosts on the stiff scene (at most ${rk4} pixels of rk4's green in the viewport in three frames, ${withoutGhosts} before G; the scene loaded: ${stiff})`);
  // P plots them in their card ("Speed against error"): each ghost a point in its colour,
  // with its name. rk4's green is looked for in the card, under its title down to the next
  // card's title, in up to three frames.
  const noPlotCard = !(await api(page)).panel["Speed against error"];
  await page.keyboard.press("p");
  await until(page, () => Boolean(window.rubberBandBox?.panel?.["Speed against error"]));
  await settle(page);
  let plotted = 0, plotArea = null;
  for (const i of [0, 1, 2]) {
    if (plotted > 10) break;
    if (i > 0) await frames(page, 2);
    const s = await api(page);
    const png = await shot(i === 0 ? "plot" : `plot-${i}`);
    const title = s.panel["Speed against error"];
    if (!title) continue;
    const next = CARDS.map((t) => s.panel[t]).filter((r) => r && r[1] > title[1]).map((r) => r[1]);
    const bottom = Math.min(s.height, ...next);
    plotArea = [title[0], title[1] + title[3], title[2], bottom - title[1] - title[3]];
    plotted = Math.max(plotted, pixels(png, green, plotArea).length);
  }
  check(plotted > 10 && noPlotCard, `P plots the ghosts in their card (at most ${plotted} pixels of rk4's green in the card ${fmt(plotArea)} in three frames; ${noPlotCard ? "no" : "a"} plot card before P)`);
  // A figure, not a check: the page's frame time with the lab on and off, side by side.
  const labFrame = await frameMs(page);
  console.log(`frame time (stiff scene, software WebGL, ${labSize.width} x ${labSize.height}): ${plainFrame.toFixed(1)} ms without the lab, ${labFrame.toFixed(1)} ms with ghosts, plot and stability line (${(labFrame / plainFrame).toFixed(2)}x)`);
  await page.keyboard.press("p");
  await page.keyboard.press("g");
  await until(page, () => !window.rubberBandBox?.panel?.Ghosts);
  lap("the lab: ghosts and plot");

  // The Controls card: its title unfolds it, a scene button loads that scene (its scripted
  // band is drawn), pause stops the box, the title folds it again. The page says where each
  // button lies, and the mouse clicks there.
  let places = (await api(page)).panel;
  check(Boolean(places.Controls), `the Controls card's title is on screen (${fmt(places.Controls)})`);
  if (places.Controls) {
    const opened = await openCard(page, "Controls", mouse);
    const listed = await until(page, () => Boolean(window.rubberBandBox?.panel?.pause));
    check(opened && listed, `clicking the "Controls" title opens its card (title lit: ${opened}; its "pause" listed: ${listed})`);
    await settle(page);
    if (await pressButton(page, "tutorial", mouse)) {
      // The script pulls from its first step: the band is looked for in the viewport, a frame
      // at a time, for up to 4 s.
      let [scripted, looks] = [0, 0];
      for (const end = Date.now() + 4000; scripted <= 30 && Date.now() < end; looks++) {
        await frames(page, 1);
        const s = await api(page);
        scripted = Math.max(scripted, pixels(await shot("panel-scene"), isBand, s.viewport).length);
      }
      check(scripted > 30, `the Controls card's "tutorial" loads the scene: its scripted band is drawn (${scripted} band pixels, the most in ${looks} frames)`);
      const pull = await boxAlwaysInView(page, (label) => shot(`desktop-${label}`));
      check(pull.ok, `desktop ${labSize.width} x ${labSize.height}: the tutorial's pull played with the Controls card open, the box fully in view in every frame sampled (${pull.said})`);
    } else {
      check(false, `the Controls card's "tutorial" is on screen (${fmt((await api(page)).panel.tutorial)})`);
    }
    // Paused, the box stands still in the world (the camera may still ease: the world's
    // coordinates are read back through the scene's place) over frames drawn since.
    await pressButton(page, "pause", mouse);
    const resumes = await until(page, () => Boolean(window.rubberBandBox?.panel?.resume));
    await shot("panel-paused");
    const a = await api(page);
    const pausedAt = Date.now();
    await frames(page, 4);
    const b = await api(page);
    const pausedFor = (Date.now() - pausedAt) / 1000;
    await shot("panel-paused-later");
    const [wa, wb] = [a, b].map((s) => (s.box && s.scene ? s.box.map((c) => toWorld(s.scene, c)) : null));
    const drift = wa && wb && wa.length === wb.length ? Math.max(...wa.map((c, k) => Math.hypot(c[0] - wb[k][0], c[1] - wb[k][1]))) : Infinity;
    check(drift < 0.5, `the Controls card's "pause" stops the box (its corners moved ${drift.toFixed(3)} world px in ${b.frame - a.frame} frames, ${pausedFor.toFixed(1)} s)`);
    check(resumes, `the pause button now says "resume"`);
    if (resumes) await pressButton(page, "resume", mouse);
    await until(page, () => Boolean(window.rubberBandBox?.panel?.pause));
    await pressButton(page, "Controls", mouse);
    const folded = await until(page, () => !window.rubberBandBox?.panel?.pause && !window.rubberBandBox?.panel?.resume);
    check(folded, `clicking the "Controls" title again folds its card (its buttons no longer listed)`);
  }
  await page.setViewportSize(small);
  await settle(page);
  lap("the Controls card");

  // The stability card: explicit Euler at the tutorial's k holds (its damping outweighs its
  // growth up to k = 221 at 100 Hz, 530 at the 240 Hz set above); three presses of ] make k
  // 2e4, past it, and the stability line turns red (at k = 20 it is not), and says so. Each
  // key waits on the status line ("euler · k 20 · 240 Hz · ..."): a key pressed again before
  // the game has read the last would be lost (two presses within one frame count once).
  const stabilityOpen = await openCard(page, "Stability", mouse);
  const stabilityLine = async (name) => {
    const png = await shot(name);
    const s = await api(page);
    const line = (s.texts ?? []).find((t) => t.text.startsWith("stability"));
    const around = line && [line.rect[0] - 2, line.rect[1] - 2, line.rect[2] + 4, line.rect[3] + 4];
    return { line, red: around ? pixels(png, isWarning, around).length : 0 };
  };
  const toIntegrator = async (name) => {
    for (let i = 0; i < 8 && statusIntegrator(await statusLine(page)) !== name; i++) {
      await pressFor(page, "i", (now, before) => statusIntegrator(now) !== statusIntegrator(before));
    }
    return statusIntegrator(await statusLine(page)) === name;
  };
  const stiffer = (factor) => (now, before) => Math.abs(statusK(now) / statusK(before) - factor) < 1e-6 * factor;
  // The keys go to the canvas (a click on a card's title leaves the focus there anyway).
  await page.focus("canvas");
  // A fresh tutorial (its clock starts over), with explicit Euler.
  sent.length = 0;
  const fresh = await pressFor(page, "1", restarted);
  const euler = await toIntegrator("euler");
  // The stability line rewritten for euler, and drawn.
  await until(page, () => (window.rubberBandBox?.texts ?? []).some((t) => t.text.startsWith("stability: euler")), null, 5000);
  await frames(page, 2);
  const holding = await stabilityLine("stability-holds");
  const kBefore = statusK(await statusLine(page));
  let stiffened = 0;
  for (let i = 0; i < 3; i++) if (await pressFor(page, "]", stiffer(10))) stiffened++;
  const kAfter = statusK(await statusLine(page));
  // The line is rewritten once a frame: until it says so, for up to 5 s, then its colour.
  await until(page, () => (window.rubberBandBox?.texts ?? []).some((t) => t.text.startsWith("stability") && t.text.includes("UNSTABLE")), null, 5000);
  await frames(page, 2);
  const past = await stabilityLine("stability-past");
  check(past.red > 30 && holding.red < 5 && /UNSTABLE/.test(past.line?.text ?? ""),
    `the stability card warns before a blow-up (card opened: ${stabilityOpen || openFailure(page)}; tutorial reloaded: ${fresh}; euler: ${euler}; k ${kBefore} to ${kAfter} by ${stiffened} of 3 presses of ], keys sent: ${sent.join(" ")}; ${past.red} red pixels past euler's limit in ${past.line ? say(past.line) : "no stability line"}; ${holding.red} at k = 20 in ${holding.line ? say(holding.line) : "no stability line"})`);
  for (let i = 0; i < 3; i++) await pressFor(page, "[", stiffer(0.1));
  await toIntegrator("auto");
  // A fresh tutorial: past euler's limit the box may have diverged.
  await pressFor(page, "1", restarted);
  lap("the stability card");

  // Learn mode by the mouse, on this page (leave puts the game back as it was).
  await walkChapters(page, `desktop ${smallSize}`, mouse, (label) => page.screenshot({ path: path.join(screens, `desktop-${label}.png`) }));
  lap("learn mode by the mouse");

  // The desktop's layout with the lab on (G, P) and every card open: the texts and the
  // viewport by the rules above; then a hand's pull out of the frame.
  await page.focus("canvas");
  await page.keyboard.press("g");
  await until(page, () => Boolean(window.rubberBandBox?.panel?.Ghosts));
  await page.keyboard.press("p");
  await until(page, () => Boolean(window.rubberBandBox?.panel?.["Speed against error"]));
  // From the bottom up: a card opened above pushes down the titles below it. Opened in the
  // small window, all of them seen lit and the layout checked at the desktop's size.
  const unopened = [];
  // Which titles are lit already, seen in one screenshot.
  const taken = { s: await api(page), png: await shot("desktop-cards") };
  for (const title of [...CARDS].reverse()) if (!(await openCard(page, title, mouse, taken))) unopened.push(openFailure(page));
  await page.setViewportSize({ width, height });
  await settle(page);
  const lab = await steady(page);
  const labPng = await shot("desktop-lab");
  const dark = titlesShown(lab).filter((t) => litIn(labPng, lab.panel[t]) === false);
  check(unopened.length === 0 && dark.length === 0, `desktop: every card opens, any number at once (not opened: ${unopened.join(", ") || "none"}; titles in view not lit: ${dark.join(", ") || "none"})`);
  checkLayout("desktop 960 x 720, the lab on, every card open", lab, 0.5);
  await page.setViewportSize(small);
  await settle(page);
  for (const target of ["corner", "dock"]) await pullAndHold(page, `desktop ${smallSize}`, mouse, (label) => shot(`desktop-lab-${label}`), target);
  lap("the desktop's layout, every card open, pulls");

  // The desktop's page is done with: the links (above).
  await openCard(page, "Controls", mouse);
  const shared = await shareOf(page, () => pressButton(page, "link", mouse));
  check(typeof shared === "string" && shared.startsWith(`${url}?v=1&`) && shared.includes("plot=on") && page.url() === shared,
    `the panel's "link" writes the link of what is on screen to the address bar (${shared}; the address ${page.url()})`);
  await page.close();
  // The fixture in a link's fragment plays back (in real time) while the links below are
  // looked at: its page in a window of 320 x 240 (only how the playback ends is read), closed
  // once it has ended.
  const fragment = zlib.deflateRawSync(fs.readFileSync(fixture), { level: 9 }).toString("base64url");
  const replaying = (async () => {
    const replayed = await openLink(desk, `${url}?v=1#replay=${fragment}`, { width: 320, height: 240 });
    const played = await replayed.waitForFunction(() => window.rubberBandBox?.playback, null, { timeout: 180000 })
      .then((handle) => handle.jsonValue()).catch(() => null);
    await replayed.close();
    return played;
  })().catch((error) => ({ error: String(error) })).then((played) => {
    check(played?.matched === true && played?.hash === nativeHash,
      `the fixture in a link's fragment (${fragment.length} characters) plays back in the page to its recorded bits (${JSON.stringify(played)})`);
  });
  if (shared) {
    // At a desktop's size, where the dock shows as the link left it.
    const again = await openLink(desk, shared, { width: 960, height: 720 });
    const back = await shareOf(again, byKey(again));
    await again.screenshot({ path: path.join(screens, "link-opened.png") });
    check(back === shared, `that link opened in a fresh page shows the same: its own C writes the same link (${back})`);
    await again.close();
  }
  lap("a link shared and opened");
  // A teacher's link to a chapter (docs/learn.md): `?learn=4` opens learn mode at chapter 4.
  const taughtPage = await openLink(desk, `${url}?v=1&learn=4`);
  const opened = await until(taughtPage, () => (window.rubberBandBox?.texts ?? []).some((t) => t.text.startsWith("4 of 8")), null, 120000);
  const fourth = await api(taughtPage);
  await taughtPage.screenshot({ path: path.join(screens, "link-to-chapter-4.png") });
  await taughtPage.close();
  check(opened && (fourth.texts ?? []).some((t) => t.text.includes("I = m (w² + h²) / 12 = ")),
    `a chapter's link (?learn=4) opens learn mode at chapter 4, its equations shown (${opened ? "opened" : "not opened"})`);
  lap("a link to a chapter");
  await takeWhatIsLeft(browser, lap);
  await replaying;
  await desk.close();
  await secondTrack;

  check(errors.length === 0, `no console errors${errors.length ? ": " + errors.join(" | ") : ""}`);
  console.log(`first frame (desktop): ${firstFrameMs} ms after navigation, ${firstFrameBytes} bytes transferred`);
  console.log(`browser test: ${((Date.now() - began) / 1000).toFixed(1)} s in all, ${failures.length} of its checks failed`);
} finally {
  await secondBrowser?.close();
  await browser.close();
  server.close();
}
process.exit(failures.length === 0 ? 0 : 1);
