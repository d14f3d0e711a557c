// What the browser test and the monkey read of the page's published layout
// (window.rubberBandBox: rectangles are [x, y, width, height] in CSS px).

export const centre = (r) => [r[0] + r[2] / 2, r[1] + r[3] / 2];
export const contains = (r, [x, y], tolerance = 0) =>
  x >= r[0] - tolerance && x <= r[0] + r[2] + tolerance && y >= r[1] - tolerance && y <= r[1] + r[3] + tolerance;

// Where to press a button: the page lists a scrolled-away button's rectangle too, but its
// label's text only where the dock shows it; so the button can be pressed where its text shows
// across the button's middle.
export const pressPoint = (s, label) => {
  const r = s.panel[label];
  if (!r || !s.texts) return null;
  const y = r[1] + r[3] / 2;
  const text = s.texts.find((t) => t.text === label && t.rect[1] <= y && t.rect[1] + t.rect[3] >= y &&
    t.rect[0] >= r[0] - 1 && t.rect[0] + t.rect[2] <= r[0] + r[2] + 1);
  return text ? [text.rect[0] + text.rect[2] / 2, y] : null;
};
