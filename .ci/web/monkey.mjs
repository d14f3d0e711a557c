// node .ci/web/monkey.mjs SITE: the monkey in the browser (issue 51). Random input from a fixed
// seed for a minute (MONKEY_SEED, MONKEY_SECONDS; another seed for as long as one likes:
// MONKEY_SEED=7 MONKEY_SECONDS=600 node .ci/web/monkey.mjs site), through the real pointer,
// finger, wheel and keys, on the page and off it, up to three presses of a key at once, every
// button of the panel but save and open, and resizes from a phone's to a desktop's, at
// 960 x 720 with touch. Every few inputs the page's published box (window.rubberBandBox.box,
// CSS px) must be finite and in its viewport (the camera may take a moment to catch a box put
// far away). At the end S saves the game, which must step in the page
// (window.rubberBandBox.replayHash) and natively (NATIVE_BINARY, `simulate --replay FILE
// --hash`) to the hash it ends with. A failure prints the seed and its last inputs; the saved
// game is kept in SITE/screens/monkey-SEED.jsonl. Exits 1 on a failure.
import { chromium } from "playwright-core";
import fs from "node:fs";
import path from "node:path";
import { execFileSync } from "node:child_process";
import { serve } from "./serve.mjs";
import { centre, contains, pressPoint } from "./page.mjs";

const site = path.resolve(process.argv[2] ?? "site");
const screens = path.join(site, "screens");
fs.mkdirSync(screens, { recursive: true });
const seed = Number(process.env.MONKEY_SEED ?? 1);
const seconds = Number(process.env.MONKEY_SECONDS ?? 60);

// mulberry32: the same inputs for a seed on every machine.
let state = seed >>> 0;
const random = () => {
  state = (state + 0x6d2b79f5) >>> 0;
  let t = state;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};
const pick = (list) => list[Math.floor(random() * list.length)];
const sizes = [[960, 720], [390, 844], [844, 390], [1280, 720], [320, 480]];
// Every key of the controls but S (the end's) and O (a file chooser), and a few others.
const keys = ["Space", "n", "r", "i", "[", "]", "-", "=", "PageDown", "PageUp", "v", "t", "g", "p", "h", "f",
  "1", "2", "3", "4", "5", "6", "7", "8", "9", "0", "c", "u", "l", "Escape", "Tab", "ArrowLeft", "z"];

// Kinds of input not sent (their randomness still drawn, so the rest is the same): a failing
// seed's input narrowed down, as in MONKEY_SKIP=touch,wheel.
const skip = (process.env.MONKEY_SKIP ?? "").split(",");
const failures = [];
const check = (ok, message) => { console.log(`${ok ? "ok  " : "FAIL"} ${message}`); if (!ok) failures.push(message); };
const api = (p) => p.evaluate(() => {
  const a = window.rubberBandBox ?? {};
  return { panel: a.panel ?? {}, viewport: a.viewport ?? null, texts: a.texts ?? null, box: a.box ?? null };
});
const fmt = (r) => JSON.stringify(r, (_, v) => (typeof v === "number" ? Math.round(v * 10) / 10 : v));
// What the status line and the readouts say now, for a failure's message.
const said = async (p) => ((await api(p)).texts ?? []).map((t) => t.text).filter((t) => / · t |saved|recording|behind/.test(t)).join(" | ");

const { url, server } = await serve(site);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  args: ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist",
    "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run"],
});
const errors = [];
const script = [];
try {
  const context = await browser.newContext({ viewport: { width: 960, height: 720 }, hasTouch: true, deviceScaleFactor: 1, acceptDownloads: true });
  const p = await context.newPage();
  p.on("pageerror", (e) => { if (!String(e).includes("Using exceptions for control flow")) errors.push(String(e)); });
  let crashed = null;
  p.on("crash", () => { crashed = script.at(-1) ?? "the start"; });
  const consoleErrors = [];
  p.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") consoleErrors.push(m.text().slice(0, 300)); });
  await p.goto(url);
  await p.waitForFunction(() => Boolean(window.rubberBandBox?.panel?.instruments), null, { timeout: 120000 });
  const cdp = await context.newCDPSession(p);
  const touch = (type, touchPoints) => cdp.send("Input.dispatchTouchEvent", { type, touchPoints });
  let size = [960, 720], held = false, touching = false, samples = 0, outOfView = 0, worst = 0, broken = null;
  const end = Date.now() + seconds * 1000;
  for (let input = 0; Date.now() < end && !broken; input++) {
    const r = random();
    const at = [(random() * 1.3 - 0.15) * size[0], (random() * 1.3 - 0.15) * size[1]];
    if (r < 0.3) {
      const mouse = skip.includes("mouse") ? { up: async () => {}, down: async () => {}, move: async () => {} } : p.mouse;
      if (held && random() < 0.3) { await mouse.up(); held = false; script.push("mouse up"); }
      else {
        await mouse.move(...(skip.includes("offpage") ? [Math.min(Math.max(at[0], 0), size[0] - 1), Math.min(Math.max(at[1], 0), size[1] - 1)] : at));
        if (!held && random() < 0.4) { await mouse.down(); held = true; }
        script.push(`mouse at ${at.map(Math.round)} held ${held}`);
      }
    } else if (r < 0.45) {
      const phase = touching ? pick(["touchMove", "touchMove", "touchEnd"]) : "touchStart";
      // A finger is on the screen: it lands and moves inside the page (a touch dispatched
      // outside it, which no finger makes, hung headless Chromium's page: docs/testing.md).
      const on = [Math.min(Math.max(at[0], 0), size[0] - 1), Math.min(Math.max(at[1], 0), size[1] - 1)];
      if (!skip.includes("touch")) await touch(phase, phase === "touchEnd" ? [] : [{ x: on[0], y: on[1] }]);
      touching = phase !== "touchEnd";
      script.push(`finger ${phase} at ${on.map(Math.round)}`);
    } else if (r < 0.5) {
      const dy = (random() - 0.5) * 600;
      if (!skip.includes("wheel")) await p.mouse.wheel(0, dy);
      script.push(`wheel ${Math.round(dy)}`);
    } else if (r < 0.75) {
      const key = pick(keys);
      const times = 1 + Math.floor(random() * 3);
      for (let k = 0; k < times; k++) if (!skip.includes(key) && !skip.includes("keys")) await p.keyboard.press(key);
      script.push(`key ${key} x${times}`);
    } else if (r < 0.9) {
      const s = await api(p);
      const labels = Object.keys(s.panel).filter((label) => label !== "save" && label !== "open");
      if (labels.length) {
        const label = pick(labels);
        if (!skip.includes("click") && !skip.includes(label)) await p.mouse.click(...(pressPoint(s, label) ?? centre(s.panel[label])));
        script.push(`click ${label}`);
      }
    } else if (r < 0.93) {
      size = pick(sizes);
      await p.setViewportSize({ width: size[0], height: size[1] });
      script.push(`resize ${size}`);
    }
    await p.waitForTimeout(Math.floor(random() * 80));
    if (process.env.MONKEY_TIMES) script[script.length - 1] += ` @${((Date.now() - end) / 1000 + seconds).toFixed(1)}s`;
    if (crashed || !p.url().startsWith(url)) {
      broken = `the page is gone after "${script.at(-1)}" (${crashed ? "its renderer crashed after " + crashed : "at " + p.url().slice(0, 100)}); its last console errors and warnings: ${consoleErrors.slice(-5).join(" | ") || "none"}`;
    }
    if (input % 8 === 0) {
      const s = await api(p);
      samples++;
      // The page itself still there (an address too long for the browser loses it).
      if (!p.url().startsWith(url) || !s.viewport) {
        broken = `the page is gone: at ${p.url().slice(0, 100)} (${p.url().length} characters), publishing ${s.viewport ? "" : "no "}viewport`;
      }
      const finite = (s.box ?? []).every((c) => c.every(Number.isFinite)) && (s.viewport ?? []).every(Number.isFinite);
      if (!finite) broken = `a published number is not finite: box ${fmt(s.box)}, viewport ${fmt(s.viewport)}`;
      const shown = s.box?.length && s.viewport && s.viewport[2] > 1 && s.viewport[3] > 1;
      const inside = shown && s.box.every((c) => contains(s.viewport, c, 1));
      outOfView = !shown || inside ? 0 : outOfView + 1;
      worst = Math.max(worst, outOfView);
      // About five seconds of samples: longer than the camera takes to catch any box.
      if (outOfView > 12) broken = `the box out of its viewport for ${outOfView} samples: box ${fmt(s.box)}, viewport ${fmt(s.viewport)}`;
    }
  }
  if (held && !skip.includes("mouse")) await p.mouse.up();
  if (touching && !skip.includes("touch")) await touch("touchEnd", []);
  const last = () => script.slice(-(Number(process.env.MONKEY_TAIL ?? 40))).join("; ");
  check(!broken, `monkey, seed ${seed}: ${script.length} inputs in ${seconds} s, ${samples} samples of the page, the box in view (at most ${worst} samples in a row out)${broken ? ": " + broken + "\n  last inputs: " + last() : ""}`);
  // Keys reach the game while its canvas has the focus.
  const focused = await p.focus("canvas", { timeout: 10000 }).then(() => true, () => false);
  if (!focused) {
    await p.screenshot({ path: path.join(screens, `monkey-${seed}-end.png`) });
    check(false, `monkey, seed ${seed}: the page has no canvas to focus at the end (at ${p.url().slice(0, 120)}; page errors: ${errors.join(" | ") || "none"})\n  last inputs: ${last()}`);
  }
  const [download] = await Promise.all([p.waitForEvent("download", { timeout: 120000 }).catch(() => null), p.keyboard.press("s")]);
  if (download) {
    const saved = path.join(screens, `monkey-${seed}.jsonl`);
    await download.saveAs(saved);
    const text = fs.readFileSync(saved, "utf8");
    const endRecord = JSON.parse(text.trim().split("\n").at(-1));
    const inPage = await p.evaluate((text) => window.rubberBandBox?.replayHash(text), text);
    let stepped = "not stepped natively (NATIVE_BINARY unset)";
    if (process.env.NATIVE_BINARY) {
      try {
        stepped = execFileSync(process.env.NATIVE_BINARY, ["simulate", "--replay", saved, "--hash"], { encoding: "utf8", maxBuffer: 1 << 20 }).trim();
      } catch (error) {
        stepped = `exit ${error.status}: ${String(error.stderr).trim()}`;
      }
    }
    const natively = stepped === endRecord.hash || (!process.env.NATIVE_BINARY && process.env.CI !== "true");
    check(inPage === endRecord.hash && natively,
      `monkey, seed ${seed}: its game saved (${endRecord.steps} steps, ${(text.length / 1e6).toFixed(1)} MB, hash ${endRecord.hash}) steps in the page (${inPage}) and natively (${stepped}) to that hash${inPage === endRecord.hash && natively ? "" : "\n  last inputs: " + last()}`);
  } else {
    check(false, `monkey, seed ${seed}: S offered no download after the monkey (the page says: ${await said(p)})\n  last inputs: ${last()}`);
  }
  await context.close();
  check(errors.length === 0, `monkey, seed ${seed}: no page errors${errors.length ? ": " + errors.join(" | ") : ""}`);
} finally {
  await browser.close();
  server.close();
}
process.exit(failures.length === 0 ? 0 : 1);
