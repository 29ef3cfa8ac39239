/* xodrcheck report page: one map and one findings list per file; filters, selection, rule documentation. */
var XC = window.XC || (window.XC = {});

function num(text) { return text === undefined || text === "" ? null : Number(text); }

/** The finding a row stands for, read from its data attributes (the page's DOM contract). */
XC.rowFinding = function (row) {
  var d = row.dataset;
  return { index: Number(d.index), code: d.code, severity: d.severity, category: d.category, road: d.road || null,
           lane: num(d.lane), sectionS: num(d.sectionS), s: num(d.s), x: num(d.x), y: num(d.y) };
};

XC.FileView = function (root) {
  this.root = root;
  this.rows = Array.prototype.slice.call(root.querySelectorAll(".xc-row"));
  this.findings = this.rows.map(XC.rowFinding);
  this.mapBox = root.querySelector(".xc-map");
  this.map = null;
  this.bindFilters();
  this.bindRows();
};

var F = XC.FileView.prototype;

F.startMap = function () {
  if (this.map || !this.mapBox) return;
  var script = this.root.querySelector("script.xc-map-data"), self = this;
  if (!script) return;
  var data = JSON.parse(script.textContent);
  this.map = new XC.MapView(this.mapBox, data, {
    onMarker: function (marker) { self.choose(marker.index, true); }
  });
  var infoBox = this.root.querySelector("[data-tool=info-markers]"), showInfo = !!(infoBox && infoBox.checked);
  this.map.setMarkers(this.findings.filter(function (f) { return f.x !== null && f.y !== null; }).map(function (f) {
    var row = self.rows[f.index];
    return { index: f.index, x: f.x, y: f.y, severity: f.severity, hidden: row.hidden,
             muted: f.severity === "info" && !showInfo,  // off the map until "info markers" is ticked
             label: f.code + " " + row.querySelector(".xc-name").textContent };
  }));
  this.legend(data);
  this.bindTools();
  XC.attachRoutes(this.map, data);  // route.js: routes between clicked lanes, unreachable lanes shaded
};

F.legend = function () {
  var box = this.root.querySelector(".xc-legend");
  if (!box) return;
  this.map.types.forEach(function (type) {
    var item = document.createElement("span"), swatch = document.createElement("i");
    swatch.style.background = XC.LANE_COLORS[type] || "#b0b0b0";
    item.appendChild(swatch);
    item.appendChild(document.createTextNode(type));
    box.appendChild(item);
  });
  if (!this.map.sections.some(function (sec) { return sec.junction !== null; })) return;
  var j = document.createElement("span"), sw = document.createElement("i");
  sw.className = "xc-junction-swatch";
  j.appendChild(sw); j.appendChild(document.createTextNode("junction"));
  box.appendChild(j);
};

F.bindTools = function () {
  var map = this.map, root = this.root;
  function on(name, fn) { var el = root.querySelector("[data-tool=" + name + "]"); if (el) el.addEventListener("click", fn); }
  on("zoom-in", function () { map.zoomAt(map.width / 2, map.height / 2, 1.5); });
  on("zoom-out", function () { map.zoomAt(map.width / 2, map.height / 2, 1 / 1.5); });
  on("fit", function () { map.fit(); });
  var ref = root.querySelector("[data-tool=reference]");
  if (ref) ref.addEventListener("change", function () { map.showReference = ref.checked; map.request("full"); });
  var info = root.querySelector("[data-tool=info-markers]");
  if (info) info.addEventListener("change", function () {
    map.markers.forEach(function (m) { if (m.severity === "info") m.muted = !info.checked; });
    map.request("overlay");
  });
};

F.bindFilters = function () {
  var self = this;
  this.root.querySelectorAll("[data-filter]").forEach(function (el) {
    el.addEventListener(el.type === "search" ? "input" : "change", function () { self.applyFilters(); });
  });
};

F.applyFilters = function () {
  var root = this.root, shown = 0;
  var severities = {};
  root.querySelectorAll("input[data-filter=severity]").forEach(function (box) { severities[box.value] = box.checked; });
  var category = (root.querySelector("[data-filter=category]") || {}).value || "";
  var code = (root.querySelector("[data-filter=code]") || {}).value || "";
  var roadText = ((root.querySelector("[data-filter=road]") || {}).value || "").trim();
  var roads = roadText ? roadText.split(/[\s,]+/).filter(Boolean) : [];
  this.rows.forEach(function (row) {
    var d = row.dataset;
    var ok = severities[d.severity] !== false && (!category || d.category === category) && (!code || d.code === code) &&
             (!roads.length || roads.indexOf(d.road || "") >= 0);
    row.hidden = !ok;
    if (ok) shown++;
  });
  var count = root.querySelector(".xc-shown");
  if (count) count.textContent = String(shown);
  if (this.map) {
    var rows = this.rows;
    this.map.markers.forEach(function (m) { m.hidden = rows[m.index].hidden; });
    this.map.request("overlay");
  }
};

F.bindRows = function () {
  var self = this;
  this.rows.forEach(function (row, i) {
    row.addEventListener("click", function (e) {
      if (e.target.closest(".xc-doc")) return;
      self.choose(i, false);
    });
    row.addEventListener("keydown", function (e) {
      if (e.key === "Enter" || e.key === " ") { e.preventDefault(); self.choose(i, false); }
    });
  });
};

/** Select finding i: mark its row, zoom the map to it and highlight its lane (or road). */
F.choose = function (i, fromMap) {
  var f = this.findings[i], row = this.rows[i];
  this.rows.forEach(function (r) { r.classList.toggle("xc-selected", r === row); r.setAttribute("aria-selected", r === row); });
  if (fromMap) row.scrollIntoView({ block: "nearest" });
  this.startMap();
  var map = this.map;
  if (!map) return;
  var lanes = f.road === null ? [] : map.lanesOf(f.road, f.sectionS, f.lane, f.s);
  map.setHighlight(lanes);
  map.select(i);
  if (f.x !== null && f.y !== null) {
    if (!fromMap) map.centerOn(f.x, f.y);
  } else if (lanes.length) {
    map.fitBox(map.lanesBox(lanes));
  }
};

XC.showDoc = function (code) {
  var docs = XC.ruleDocs || {}, rule = docs[code], dialog = document.getElementById("xc-doc");
  if (!dialog) return;
  dialog.querySelector(".xc-doc-title").textContent = rule ? code + " " + rule.name : code;
  dialog.querySelector(".xc-doc-meta").textContent =
    rule ? rule.category + " · " + rule.severity + (rule.basis ? " · basis: " + rule.basis : "") : "";
  var text = dialog.querySelector(".xc-doc-text");
  if (rule) text.innerHTML = rule.html;  // rendered and escaped by the page's writer (xodrcheck.rules.docformat)
  else text.textContent = "No documentation for this code.";
  if (dialog.showModal) dialog.showModal(); else dialog.setAttribute("open", "");
};

XC.boot = function () {
  var docs = document.getElementById("xc-rule-docs");
  XC.ruleDocs = docs ? JSON.parse(docs.textContent) : {};
  document.addEventListener("click", function (e) {
    var doc = e.target.closest ? e.target.closest(".xc-doc") : null;
    if (doc) { e.preventDefault(); XC.showDoc(doc.dataset.code); }
    if (e.target.closest && e.target.closest(".xc-doc-close")) document.getElementById("xc-doc").close();
  });
  var views = Array.prototype.map.call(document.querySelectorAll(".xc-file"), function (el) {
    return (el.xcView = new XC.FileView(el));
  });
  XC.views = views;
  var lazy = views.length > 1 && window.IntersectionObserver;
  if (!lazy) { views.forEach(function (v) { v.startMap(); }); return; }
  var watcher = new IntersectionObserver(function (entries) {
    entries.forEach(function (entry) { if (entry.isIntersecting) entry.target.closest(".xc-file").xcView.startMap(); });
  }, { rootMargin: "200px" });
  views.forEach(function (v) { if (v.mapBox) watcher.observe(v.mapBox); });
};

if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", XC.boot); else XC.boot();
