#include "report/report_page_assets.hpp"

namespace canopy {

std::string_view report_page_style() {
    return R"CSS(
body { font-family: system-ui, sans-serif; margin: 1.5em auto; max-width: 1600px; padding: 0 1em; color: #222; }
h1 { font-size: 1.5em; } h2 { border-bottom: 1px solid #ccc; margin-top: 2em; }
table { border-collapse: collapse; margin: 0.5em 0 1em; font-size: 0.85em; }
.table-scroll { overflow-x: auto; max-width: 100%; }
th, td { border: 1px solid #ddd; padding: 2px 6px; } th { background: #f3f3f3; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.sortable th { cursor: pointer; user-select: none; }
table.sortable th.sorted-ascending::after { content: " \25B2"; } table.sortable th.sorted-descending::after { content: " \25BC"; }
tr.dominated td { color: #888; }
.environment td:first-child { font-weight: bold; }
.warning { background: #fff3cd; padding: 0.5em; border: 1px solid #e0c36b; }
.charts { display: flex; flex-wrap: wrap; gap: 1em; } .chart { border: 1px solid #eee; padding: 0.5em; min-width: 0; max-width: 100%; box-sizing: border-box; }
svg.pareto { max-width: 100%; height: auto; }
svg.pareto circle { cursor: default; }
.case { margin: 1em 0 2em; } .case h4 { margin: 0.2em 0; font-weight: normal; }
.viewer { display: grid; grid-template-columns: repeat(4, 1fr); gap: 6px; }
.panel { position: relative; overflow: hidden; background: #111; cursor: grab; aspect-ratio: var(--aspect, 16 / 9); }
.panel img { position: absolute; left: 0; top: 0; transform-origin: 0 0; image-rendering: pixelated; max-width: none; }
.panel .label { position: absolute; left: 4px; top: 2px; color: #fff; background: rgba(0,0,0,0.55); font-size: 0.75em; padding: 0 4px; z-index: 1; pointer-events: none; }
.bar { height: 10px; margin-top: 2px; } .bar-labels { display: flex; justify-content: space-between; font-size: 0.7em; }
.hint { color: #666; font-size: 0.85em; }
#selftest-result { display: none; }
)CSS";
}

std::string_view report_page_script() {
    return R"JS(
"use strict";
const pageErrors = [];
window.addEventListener("error", (e) => pageErrors.push(String(e.message || e)));
window.addEventListener("unhandledrejection", (e) => pageErrors.push("unhandled rejection: " + String(e.reason)));
const consoleError = console.error.bind(console);
console.error = (...args) => { pageErrors.push("console.error: " + args.join(" ")); consoleError(...args); };

// Sortable tables: a click on a header sorts by that column (numbers by data-value).
function sortTable(th) {
  const table = th.closest("table");
  const column = Array.from(th.parentNode.children).indexOf(th);
  const ascending = !th.classList.contains("sorted-ascending");
  for (const other of th.parentNode.children) other.classList.remove("sorted-ascending", "sorted-descending");
  th.classList.add(ascending ? "sorted-ascending" : "sorted-descending");
  const body = table.tBodies[0];
  const key = (row) => {
    const cell = row.children[column];
    if (!cell) return "";
    const v = cell.getAttribute("data-value");
    return v !== null && v !== "" ? parseFloat(v) : cell.textContent.trim();
  };
  const rows = Array.from(body.rows);
  rows.sort((a, b) => {
    const x = key(a), y = key(b);
    const bothNumbers = typeof x === "number" && typeof y === "number";
    const order = bothNumbers ? x - y : typeof x === "number" ? -1 : typeof y === "number" ? 1 : String(x).localeCompare(String(y));
    return ascending ? order : -order;
  });
  for (const row of rows) body.appendChild(row);
}

// Viewers: the panels of one case show their images with one zoom and pan.
class Viewer {
  constructor(element) {
    this.element = element;
    this.panels = Array.from(element.querySelectorAll(".panel"));
    this.scale = 1; this.x = 0; this.y = 0;
    for (const panel of this.panels) {
      panel.addEventListener("wheel", (e) => { e.preventDefault(); this.zoomAt(panel, e.offsetX, e.offsetY, e.deltaY < 0 ? 1.25 : 0.8); }, { passive: false });
      panel.addEventListener("mousedown", (e) => this.startDrag(e));
      panel.addEventListener("dblclick", () => this.set(1, 0, 0));
    }
  }
  zoomAt(panel, px, py, factor) {
    const scale = Math.min(64, Math.max(1, this.scale * factor));
    const k = scale / this.scale;
    this.set(scale, px - (px - this.x) * k, py - (py - this.y) * k, panel);
  }
  startDrag(e) {
    e.preventDefault();
    const x0 = e.clientX - this.x, y0 = e.clientY - this.y;
    const move = (m) => this.set(this.scale, m.clientX - x0, m.clientY - y0);
    const up = () => { window.removeEventListener("mousemove", move); window.removeEventListener("mouseup", up); };
    window.addEventListener("mousemove", move);
    window.addEventListener("mouseup", up);
  }
  set(scale, x, y) {
    const panel = this.panels[0];
    const w = panel ? panel.clientWidth : 0, h = panel ? panel.clientHeight : 0;
    // Keep the image over the panel.
    this.scale = scale;
    this.x = Math.min(0, Math.max(w - w * scale, x));
    this.y = Math.min(0, Math.max(h - h * scale, y));
    const transform = `translate(${this.x}px, ${this.y}px) scale(${this.scale})`;
    for (const img of this.element.querySelectorAll(".panel img")) img.style.transform = transform;
  }
}

const viewers = [];
function setUp() {
  for (const img of document.querySelectorAll("img[data-image]")) {
    const source = document.getElementById(img.getAttribute("data-image"));
    if (source) img.src = source.textContent.trim();
  }
  for (const th of document.querySelectorAll("table.sortable th")) th.addEventListener("click", () => sortTable(th));
  for (const element of document.querySelectorAll(".viewer")) viewers.push(new Viewer(element));
}

// #selftest: what tests/report/ checks in a headless browser, written into the page.
function selfTest() {
  const result = { errors: pageErrors.slice(), images: 0, broken: [], zoom_synchronised: null, sortable: null, cut_off: [] };
  for (const img of document.images) {
    result.images++;
    if (!img.complete || img.naturalWidth === 0) result.broken.push(img.alt || img.getAttribute("data-image") || img.src.slice(0, 60));
  }
  if (viewers.length > 0) {
    const viewer = viewers[0];
    const panel = viewer.panels[0];
    panel.dispatchEvent(new WheelEvent("wheel", { deltaY: -120, clientX: 10, clientY: 10, bubbles: true, cancelable: true }));
    const transforms = Array.from(viewer.element.querySelectorAll(".panel img")).map((img) => img.style.transform);
    result.zoom_synchronised = transforms.length > 1 && viewer.scale > 1 && transforms.every((t) => t === transforms[0] && t.includes("scale(1.25)"));
    viewer.set(1, 0, 0);
  }
  const table = document.getElementById("results-table");
  if (table) {
    const th = Array.from(table.tHead.rows[0].cells).find((c) => c.textContent.includes("time ratio"));
    if (th) {
      const column = Array.from(th.parentNode.children).indexOf(th);
      th.click();
      const values = Array.from(table.tBodies[0].rows).map((r) => parseFloat(r.children[column].getAttribute("data-value"))).filter((v) => !isNaN(v));
      result.sortable = values.every((v, i) => i === 0 || values[i - 1] <= v);
    }
  }
  // Tables fit the page: every cell lies within the window's width, or inside a box that scrolls
  // it (.table-scroll) and that itself lies within the width; the page never scrolls sideways.
  const width = document.documentElement.clientWidth;
  for (const cell of document.querySelectorAll("td, th")) {
    const box = cell.closest(".table-scroll");
    const scrolls = box && ["auto", "scroll"].includes(getComputedStyle(box).overflowX);
    if ((scrolls ? box : cell).getBoundingClientRect().right > width + 1) result.cut_off.push(cell.textContent.trim().slice(0, 40));
  }
  result.page_width = { window: width, content: document.documentElement.scrollWidth };
  result.tables_fit = result.cut_off.length === 0 && document.documentElement.scrollWidth <= width;
  result.pass = result.tables_fit && result.errors.length === 0 && result.broken.length === 0 && result.zoom_synchronised !== false && result.sortable !== false;
  const out = document.getElementById("selftest-result");
  out.textContent = JSON.stringify(result);
  document.title = "selftest: " + (result.pass ? "pass" : "fail");
}

document.addEventListener("DOMContentLoaded", setUp);
window.addEventListener("load", () => { if (location.hash === "#selftest") setTimeout(selfTest, 0); });
)JS";
}

}  // namespace canopy
