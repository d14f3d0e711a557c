//! The page around the web build: the few things only JavaScript can do (download a file,
//! ask for one, receive a dropped one) and what the page can read back (a replay's hash, how a
//! playback ended, where the panel's buttons, the viewport, the texts and the box are). A leaf: no Bevy, no game state; the
//! recorder, the playback and the panel call it.

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
"#)]
extern "C" {
    /// Offers `text` as a download; the file's name.
    pub fn download_replay(text: &str) -> String;

    /// Opens the browser's file chooser (needs a recent key press or click).
    pub fn choose_replay_file();

    /// Files dropped anywhere on the page are opened.
    pub fn accept_dropped_files();

    /// The name of the file opened, if one waits (call before [`take_opened_text`]).
    pub fn take_opened_name() -> Option<String>;

    /// The text of the file opened since the last call, if any.
    pub fn take_opened_text() -> Option<String>;

    /// `window.rubberBandBox.replayHash(text)`: what `simulate --replay FILE --hash` prints.
    pub fn expose_replay_hash(hash: &Closure<dyn Fn(String) -> String>);

    /// `window.rubberBandBox.playback`: how the latest playback ended.
    pub fn publish_playback(steps: f64, hash: &str, recorded: &str, matched: bool);

    /// `window.rubberBandBox.panel`: each panel button's label and where it lies on the page
    /// (CSS pixels: x, y, width, height), so that a test can click what a player clicks.
    pub fn publish_panel(json: &str);

    /// `window.rubberBandBox.scene`: where the tutorial's 640 x 480 screen is drawn on the
    /// page (CSS pixels: x, y, width, height), so that a test can find the world on it.
    pub fn publish_scene(x: f32, y: f32, width: f32, height: f32);

    /// `window.rubberBandBox.viewport`: the scene's viewport on the page (CSS pixels: x, y,
    /// width, height).
    pub fn publish_viewport(x: f32, y: f32, width: f32, height: f32);

    /// `window.rubberBandBox.texts`: every text shown, `{ text, rect: [x, y, width, height] }`
    /// (CSS pixels; the part a scrolled dock shows).
    pub fn publish_texts(json: &str);

    /// The page's address: the game opens the link it is (`replay::link`).
    pub fn page_address() -> String;

    /// `query` (`?v=1&...#replay=...`) on the page's address: made the address shown, copied
    /// to the clipboard where the browser allows, kept as `window.rubberBandBox.link`. The
    /// whole address.
    pub fn share_link(query: &str) -> String;

    /// `window.rubberBandBox.box`: the box's corners on the page, `[[x, y], ...]` (CSS pixels).
    pub fn publish_box(json: &str);
}
