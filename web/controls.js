// The log list, the selection, and the parameter forms.
import { $, fmt, state, VIEW_KIND, logFor } from "./state.js";
import { render, scheduleRender } from "./render.js";
import { saveRecipe, fixTimeOrder, readJoined } from "./loading.js";
import { forget } from "./background.js";

// ---------- list and selection ----------
export function renderList() {
  const ul = $("logs");
  ul.replaceChildren();
  const shown = logFor(state.view);
  state.entries.forEach((e, i) => {
    const li = document.createElement("li");
    if (e.error) {
      li.className = "bad";
      const text = document.createElement("span");
      text.textContent = e.error;
      li.append(text, removeButton(i, `Dismiss the error of ${e.name}`));
      li.dataset.error = "1";
      if (e.timeOrder) {
        const title = "Merge rows of one time (each column's mean) and sort rows up to 1 s late in, as gyrodrift --time-order fix";
        li.append(fixButton("fix-order", "put in time order", title, `Put ${e.name} in time order and open it`, () => fixTimeOrder(e)));
      }
      if (e.joined) {
        const title = "Open each log joined in the file (or each part after a clock reset) as a log of its own, as gyrodrift split writes them";
        li.append(fixButton("fix-joined", "read each log", title, `Read each log joined in ${e.name}`, () => readJoined(e)));
      }
    } else {
      // the highlighted log is the one the view plots
      if (e === shown) {
        li.className = "selected";
        li.setAttribute("aria-current", "true");
      }
      const b = document.createElement("button");
      b.className = "pick";
      b.innerHTML = `<div><b></b></div><div class="meta"></div>`;
      b.querySelector("b").textContent = e.name;
      b.querySelector(".meta").textContent = `${e.kind} · ${fmt(e.log.durationMin, 1)} min · ${e.headline}`;
      b.addEventListener("click", () => selectEntry(i));
      li.append(b, removeButton(i, `Remove ${e.name}`));
      if (state.view === "hdr" && e.kind === "drive" && e !== shown) li.append(overlayButton(e));
      if (e.findings?.length) {
        const worst = e.errors.length ? "error" : "warning";
        li.append(checkNote(worst, `⚠ check: ${e.findings.map((f) => f.code).join(", ")}`, said(e.findings)));
      }
      if (e.info?.length) li.append(checkNote("info", `ℹ ${e.info.map((f) => f.code.replace("_", " ")).join(", ")}`, said(e.info)));
      if (e.imported) {
        const imp = document.createElement("div");
        imp.className = "check imported";
        const u = e.imported.used.map(([role, f]) => `${role} = ${f}`).join(", ");
        imp.textContent = `⇢ imported: ${e.imported.title}`;
        imp.title = `${u}${e.imported.ignored.length ? `; not used: ${e.imported.ignored.join(", ")}` : ""}`;
        const save = document.createElement("button");
        save.type = "button";
        save.className = "link";
        save.textContent = "recipe";
        save.title = "Save the recipe (TOML): drop it with the files again, or gyrodrift import --recipe";
        save.setAttribute("aria-label", `Save the import recipe of ${e.name}`);
        save.addEventListener("click", () => saveRecipe(e.name, e.imported.recipe));
        imp.append(" ", save);
        li.append(imp);
      }
      if (e.note) li.append(checkNote("split", "✂ split at a gap in time", [e.note]));
      if (e.orderNote) li.append(checkNote("split", e.orderLabel, [e.orderNote]));
    }
    ul.append(li);
  });
}

/** A check's findings as each says them: the message, then its fix. */
export const said = (findings) => findings.map((f) => `${f.message}${f.fix ? ` — fix: ${f.fix}` : ""}`);

/** A link-styled button on an error entry that reads its file again another way. */
function fixButton(kind, text, title, label, onClick) {
  const b = document.createElement("button");
  b.type = "button";
  b.className = `link ${kind}`;
  b.textContent = text;
  b.title = title;
  b.setAttribute("aria-label", label);
  b.addEventListener("click", onClick);
  return b;
}

/** A note on a log: its summary in the list, what it says under it, opened by a click, a tap
 * or the keyboard (a tooltip alone shows nothing on a phone), and on hover as before. */
function checkNote(kind, summary, lines) {
  const note = document.createElement("details");
  note.className = `check ${kind}`;
  note.title = lines.join("\n");
  const head = document.createElement("summary");
  head.textContent = summary;
  note.append(head, ...lines.map((l) => Object.assign(document.createElement("p"), { textContent: l })));
  return note;
}

/** Overlays a drive on the HDR view's error and column charts (or takes it off). */
function overlayButton(e) {
  const b = document.createElement("button");
  b.type = "button";
  b.className = "link overlay";
  const on = state.overlay.has(e.name);
  b.textContent = on ? "overlaid ✓" : "overlay";
  b.setAttribute("aria-pressed", String(on));
  b.setAttribute("aria-label", `Overlay ${e.name} on the HDR charts`);
  b.addEventListener("click", () => {
    if (state.overlay.has(e.name)) state.overlay.delete(e.name);
    else state.overlay.add(e.name);
    renderList();
    render();
  });
  return b;
}

function removeButton(i, label) {
  const x = document.createElement("button");
  x.className = "remove";
  x.type = "button";
  x.textContent = "×";
  x.title = label;
  x.setAttribute("aria-label", label);
  x.addEventListener("click", () => removeEntry(i));
  return x;
}

/** Removes a log (its wasm memory freed) or dismisses an error entry. */
export function removeEntry(i) {
  const [e] = state.entries.splice(i, 1);
  if (e) forget(e);
  e?.log?.free();
  if (state.selected > i || state.selected >= state.entries.length) state.selected--;
  state.selected = Math.max(0, Math.min(state.selected, state.entries.length - 1));
  state.zoom = null;
  renderList(); // the list may have been drawn outside render() (a failed load)
  render();
}

export function selectEntry(i) {
  state.selected = i;
  state.zoom = null;
  state.cursor = null;
  const want = VIEW_KIND[state.view];
  const kind = state.entries[i]?.kind;
  if (want && kind && kind !== want) {
    const v = Object.keys(VIEW_KIND).find((k) => VIEW_KIND[k] === kind) || (kind === "static" ? "allan" : state.view);
    state.view = v;
  }
  render();
}

/** The selected log if it suits the view, else the first loaded one that does (state.js). */
export { logFor };

// ---------- parameters ----------
/** A form of parameters, slider and box each. `check(key, value)` asks core whether the
 * value is valid (null) or why not: a bad, empty or out-of-range value is refused in place,
 * with the reason beside the box, and the settings, slider, results and URL keep the last
 * valid value. */
export function buildParams(form, list, get, set, extra, check) {
  form.replaceChildren();
  for (const p of list) {
    const row = document.createElement("div");
    row.className = "param";
    const id = `p-${p.key}`;
    row.innerHTML = `<label for="${id}"></label><input type="range" id="${id}"><input type="number" aria-label=""><span class="unit"></span><span class="param-error" role="alert"></span>`;
    row.querySelector("label").textContent = p.label;
    row.querySelector(".unit").textContent = p.unit;
    const [range, num] = row.querySelectorAll("input");
    if (p.help) for (const el of [row.querySelector("label"), range, num]) el.title = p.help;
    const msg = row.querySelector(".param-error");
    num.id = `${id}-value`;
    num.setAttribute("aria-label", `${p.label} (${p.unit || "no unit"})`);
    num.setAttribute("aria-describedby", `${id}-error`);
    msg.id = `${id}-error`;
    for (const el of [range, num]) Object.assign(el, { min: p.min, max: p.max, step: p.step });
    const showWhy = (why) => {
      msg.textContent = why ? `${why} (kept ${get(p.key)})` : "";
      row.classList.toggle("invalid", !!why);
      if (why) num.setAttribute("aria-invalid", "true");
      else num.removeAttribute("aria-invalid");
    };
    const sync = () => {
      const v = get(p.key);
      range.value = v;
      num.value = v;
      showWhy(null);
    };
    const onInput = (el) => () => {
      const text = String(el.value).trim();
      const v = Number(text);
      const why = el.validity?.badInput || (text !== "" && !Number.isFinite(v)) ? "not a number"
        : text === "" ? "enter a number"
        : check?.(p.key, v) || null;
      if (why) return showWhy(why);
      showWhy(null);
      set(p.key, v);
      (el === range ? num : range).value = v;
      scheduleRender();
    };
    range.addEventListener("input", onInput(range));
    num.addEventListener("change", onInput(num));
    row.sync = sync;
    sync();
    form.append(row);
  }
  if (extra) extra(form);
}

export function syncParams() {
  for (const row of document.querySelectorAll(".param")) row.sync?.();
  const rs = $("p-resample");
  if (rs) rs.checked = state.resample;
}
