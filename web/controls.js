// The log list, the selection, and the parameter forms.
import { $, fmt, state, VIEW_KIND } from "./state.js";
import { render, scheduleRender } from "./render.js";

// ---------- list and selection ----------
export function renderList() {
  const ul = $("logs");
  ul.replaceChildren();
  state.entries.forEach((e, i) => {
    const li = document.createElement("li");
    if (e.error) {
      li.className = "bad";
      li.textContent = e.error;
      li.dataset.error = "1";
    } else {
      if (i === state.selected) li.className = "selected";
      const b = document.createElement("button");
      b.className = "pick";
      b.innerHTML = `<div><b></b></div><div class="meta"></div>`;
      b.querySelector("b").textContent = e.name;
      b.querySelector(".meta").textContent = `${e.kind} · ${fmt(e.log.durationMin, 1)} min · ${e.headline}`;
      b.addEventListener("click", () => selectEntry(i));
      li.append(b);
      if (e.findings?.length) {
        const badge = document.createElement("div");
        const worst = e.findings.some((f) => f.severity === "error") ? "error" : "warning";
        badge.className = `check ${worst}`;
        badge.textContent = `⚠ check: ${e.findings.map((f) => f.code).join(", ")}`;
        badge.title = e.findings.map((f) => `${f.message}${f.fix ? ` — fix: ${f.fix}` : ""}`).join("\n");
        li.append(badge);
      }
      if (e.note) {
        const note = document.createElement("div");
        note.className = "check split";
        note.textContent = "✂ split at a gap in time";
        note.title = e.note;
        li.append(note);
      }
    }
    ul.append(li);
  });
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

/** The selected log if it suits the view, else the first loaded one that does. */
export function logFor(view) {
  const want = VIEW_KIND[view];
  const sel = state.entries[state.selected];
  if (view === "allan") {
    // any gyro log will do, a static one is what the method is for
    if (sel && !sel.error && sel.kind === "static") return sel;
    return state.entries.find((e) => !e.error && e.kind === "static") || (sel && !sel.error ? sel : null);
  }
  if (sel && !sel.error && (!want || sel.kind === want)) return sel;
  return state.entries.find((e) => !e.error && (!want || e.kind === want)) || null;
}

// ---------- parameters ----------
export function buildParams(form, list, get, set, extra) {
  form.replaceChildren();
  for (const p of list) {
    const row = document.createElement("div");
    row.className = "param";
    const id = `p-${p.key}`;
    row.innerHTML = `<label for="${id}"></label><input type="range" id="${id}"><input type="number" aria-label=""><span class="unit"></span>`;
    row.querySelector("label").textContent = p.label;
    row.querySelector(".unit").textContent = p.unit;
    const [range, num] = row.querySelectorAll("input");
    num.setAttribute("aria-label", `${p.label} (${p.unit || "no unit"})`);
    for (const el of [range, num]) Object.assign(el, { min: p.min, max: p.max, step: p.step });
    const sync = () => {
      const v = get(p.key);
      range.value = v;
      num.value = v;
    };
    const onInput = (el) => () => {
      const v = Number(el.value);
      if (!Number.isFinite(v)) return;
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
