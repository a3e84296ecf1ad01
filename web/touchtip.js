// A touch screen shows no tooltips, and the page explains its parameters, metrics and notes
// in them (`title`). A tap on such an explanation-bearing element that is not a control
// shows its text in a popup under it; the next tap anywhere, a scroll or Escape closes it.
const CONTROLS = "button, input, select, textarea, a, summary, canvas";

export function setupTouchTips() {
  const tip = document.createElement("div");
  tip.id = "touch-tip";
  tip.setAttribute("role", "tooltip");
  tip.hidden = true;
  document.body.append(tip);
  const hide = () => { tip.hidden = true; };
  // The click's own pointerType where the browser gives one, else its pointerdown's (a
  // click is not a PointerEvent everywhere).
  let last = "mouse";
  document.addEventListener("pointerdown", (ev) => {
    last = ev.pointerType;
    if (ev.target !== tip) hide();
  }, true);
  document.addEventListener("scroll", hide, true);
  document.addEventListener("keydown", (ev) => { if (ev.key === "Escape") hide(); });
  document.addEventListener("click", (ev) => {
    if ((ev.pointerType || last) !== "touch") return;
    const el = ev.target instanceof Element ? ev.target.closest("[title]") : null;
    // (A note that opens, `details`, shows its text itself.)
    if (!el || !el.title || el.tagName === "DETAILS" || ev.target.closest(CONTROLS)) return;
    tip.textContent = el.title;
    const r = el.getBoundingClientRect();
    tip.style.left = `${Math.max(4, Math.min(r.left, window.innerWidth - 4 - Math.min(320, window.innerWidth - 8)))}px`;
    tip.style.top = `${r.bottom + 4}px`;
    tip.hidden = false;
    // Above the element where it would run off the bottom of the screen.
    const h = tip.offsetHeight;
    if (r.bottom + 4 + h > window.innerHeight) tip.style.top = `${Math.max(4, r.top - 4 - h)}px`;
  });
}
