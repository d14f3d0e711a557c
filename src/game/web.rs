//! The page around the web build: the few things only JavaScript can do (download a file, ask for
//! one, receive a dropped one) and what the page can read back (a replay's hash, how a playback
//! ended, where the panel's buttons, the viewport, the texts and the box are). A leaf: no Bevy, no
//! game state; the recorder, the playback, the panel, the access module and others call it.

use wasm_bindgen::prelude::*;

#[wasm_bindgen(inline_js = r#"
// The latest replay file the player chose or dropped, until the game takes it.
let opened = null;

function read(file) {
  if (file) file.text().then((text) => { opened = { name: file.name, text }; });
}

export function download_replay(text) {
  const name = `replay-${Math.floor(Date.now() / 1000)}.jsonl`;
  const link = document.createElement("a");
  link.href = URL.createObjectURL(new Blob([text], { type: "application/x-ndjson" }));
  link.download = name;
  document.body.appendChild(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(link.href), 60000);
  return name;
}

export function choose_replay_file() {
  const input = document.createElement("input");
  input.type = "file";
  input.accept = ".jsonl,.json,.txt,application/x-ndjson";
  input.addEventListener("change", () => read(input.files[0]));
  input.click();
}

export function accept_dropped_files() {
  window.addEventListener("dragover", (event) => event.preventDefault());
  window.addEventListener("drop", (event) => {
    event.preventDefault();
    read(event.dataTransfer?.files?.[0]);
  });
}

export function take_opened_name() {
  return opened?.name;
}

export function take_opened_text() {
  const text = opened?.text;
  opened = null;
  return text;
}

function api() {
  return (window.rubberBandBox ??= {});
}

export function expose_replay_hash(hash) {
  api().replayHash = (text) => hash(String(text));
}

export function publish_playback(steps, hash, recorded, matched) {
  api().playback = { steps, hash, recorded, matched };
}

export function publish_panel(json) {
  api().panel = JSON.parse(json);
}

export function publish_scene(x, y, width, height) {
  api().scene = [x, y, width, height];
}

export function publish_viewport(x, y, width, height) {
  api().viewport = [x, y, width, height];
}

export function publish_texts(json) {
  api().texts = JSON.parse(json);
}

export function page_address() {
  return window.location.href;
}

export function share_link(query) {
  const url = window.location.href.split(/[?#]/)[0] + query;
  try {
    history.replaceState(null, "", url);
  } catch (error) {}
  navigator.clipboard?.writeText(url).catch(() => {});
  api().link = url;
  return url;
}

export function publish_box(json) {
  api().box = JSON.parse(json);
}

// What a screen reader reads of the page: the scene described and the last action's result
// in a live region, the controls named in a list (index.html holds both elements).
export function announce(text) {
  const region = document.getElementById("said");
  if (region && region.textContent !== text) region.textContent = text;
  api().said = text;
}

export function publish_controls(json) {
  const controls = JSON.parse(json);
  api().controls = controls;
  const list = document.getElementById("controls");
  if (!list) return;
  list.replaceChildren(...controls.map(({ name, value }) => {
    const item = document.createElement("li");
    item.textContent = value ? `${name}: ${value}` : name;
    return item;
  }));
}

// The keyboard's focus in the game: its control's name, and whether it is the first or the
// last Tab reaches (index.html lets Tab leave the canvas from there).
export function publish_focus(json) {
  api().focus = JSON.parse(json);
}

// The canvas entered from the page by Tab ("first") or Shift+Tab ("last"), until the game
// takes it: as a page's own Tab order does, the game's then starts at that end. A press
// (a click on the canvas) is no Tab.
let tabbed = null;
let entered = null;
window.addEventListener("keydown", (event) => {
  if (event.key === "Tab") tabbed = event.shiftKey ? "last" : "first";
}, { capture: true });
window.addEventListener("pointerdown", () => { tabbed = null; }, { capture: true });
document.addEventListener("focusin", (event) => {
  if (event.target?.id === "bevy" && tabbed) entered = tabbed;
  tabbed = null;
}, { capture: true });

export function take_entered() {
  const end = entered;
  entered = null;
  return end;
}
"#)]
extern "C" {
    /// Offers `text` as a download and returns the file's name.
    pub fn download_replay(text: &str) -> String;

    /// Opens the browser's file chooser (needs a recent key press or click).
    pub fn choose_replay_file();

    /// Arranges for files dropped anywhere on the page to be opened.
    pub fn accept_dropped_files();

    /// Returns the name of the file opened, if one waits (call before [`take_opened_text`]).
    pub fn take_opened_name() -> Option<String>;

    /// Takes the text of the file opened since the last call, if any.
    pub fn take_opened_text() -> Option<String>;

    /// Takes the end the canvas was entered at from the page since the last call, if any.
    ///
    /// "first" after a Tab, "last" after a Shift+Tab.
    pub fn take_entered() -> Option<String>;

    /// Exposes `window.rubberBandBox.replayHash(text)`.
    ///
    /// It returns what `simulate --replay FILE --hash` prints.
    pub fn expose_replay_hash(hash: &Closure<dyn Fn(String) -> String>);

    /// Publishes `window.rubberBandBox.playback`: how the latest playback ended.
    pub fn publish_playback(steps: f64, hash: &str, recorded: &str, matched: bool);

    /// Publishes `window.rubberBandBox.panel`: each panel button's label and where it lies.
    ///
    /// Places are on the page, in CSS pixels (x, y, width, height), so that a test can click what a
    /// player clicks.
    pub fn publish_panel(json: &str);

    /// Publishes `window.rubberBandBox.scene`: where the tutorial's 640 x 480 screen is drawn.
    ///
    /// The place is on the page, in CSS pixels (x, y, width, height), so that a test can find the
    /// world on it.
    pub fn publish_scene(x: f32, y: f32, width: f32, height: f32);

    /// Publishes `window.rubberBandBox.viewport`: the scene's viewport on the page.
    ///
    /// It is in CSS pixels: x, y, width, height.
    pub fn publish_viewport(x: f32, y: f32, width: f32, height: f32);

    /// Publishes `window.rubberBandBox.texts`: every text shown, and where.
    ///
    /// Each is `{ text, rect: [x, y, width, height] }` (CSS pixels; the part a scrolled dock
    /// shows).
    pub fn publish_texts(json: &str);

    /// Returns the page's address: the game opens the link it is (`replay::link`).
    pub fn page_address() -> String;

    /// Puts `query` (`?v=1&...#replay=...`) on the page's address and returns the whole address.
    ///
    /// The address is made the one shown, copied to the clipboard where the browser allows, and
    /// kept as `window.rubberBandBox.link`.
    pub fn share_link(query: &str) -> String;

    /// Publishes `window.rubberBandBox.box`: the box's corners on the page.
    ///
    /// They are `[[x, y], ...]`, in CSS pixels.
    pub fn publish_box(json: &str);

    /// Puts `text` in the page's live region (`#said`), which a screen reader reads out.
    ///
    /// Also `window.rubberBandBox.said`.
    pub fn announce(text: &str);

    /// Publishes `window.rubberBandBox.controls` and lists them in the page (`#controls`).
    ///
    /// Each is `{ name, value }`: every control the dock shows, named as a screen reader names it.
    pub fn publish_controls(json: &str);

    /// Publishes `window.rubberBandBox.focus`: `{ name, first, last }` of the focused control.
    ///
    /// It is `null` when the scene has the focus.
    pub fn publish_focus(json: &str);
}
