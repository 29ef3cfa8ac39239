/* xodrcheck map view: the decoded map drawn on a canvas, with pan, zoom, hover and finding markers. */
var XC = window.XC || (window.XC = {});

XC.LANE_COLORS = {
  driving: "#62666d", bidirectional: "#676b73", entry: "#6c6f77", exit: "#6c6f77", onRamp: "#6c6f77",
  offRamp: "#6c6f77", connectingRamp: "#6c6f77", mwyEntry: "#6c6f77", mwyExit: "#6c6f77", slipLane: "#6c6f77",
  bus: "#8a5f5f", taxi: "#8a7b4e", HOV: "#6d5f8a", stop: "#7b7060", shoulder: "#a19f90", border: "#aaa9a0",
  restricted: "#b99393", parking: "#7f91a8", biking: "#b3715f", sidewalk: "#cdbfa6", walking: "#d8cbae",
  curb: "#c2c2c2", median: "#88aa74", tram: "#8c7760", rail: "#7c6651", roadWorks: "#d39b3d",
  special1: "#9b90b2", special2: "#9b90b2", special3: "#9b90b2", none: "#9a9a96"
};
XC.MARK_COLORS = { standard: "#ffffff", white: "#ffffff", yellow: "#f2c200", red: "#e0443a", blue: "#3a78e0",
                   green: "#3aa35a", orange: "#f08a24", violet: "#8a4ae0", black: "#222222" };
XC.SEVERITY_COLORS = { error: "#d7263d", warning: "#f29e2e", info: "#2e86de" };
var BACKGROUND = "#eef0ea", JUNCTION_TINT = "rgba(70, 110, 220, 0.22)", HIGHLIGHT = "#00c8ff";
var MIN_SCALE_FACTOR = 0.25, MAX_SCALE = 400, FOCUS_SCALE = 12;

XC.MapView = function (container, data, options) {
  this.container = container;
  this.options = options || {};
  this.origin = data.origin;
  var started = performance.now();
  this.sections = XC.decodeMap(data);
  this.cells = XC.buildCells(this.sections, 250);
  this.timings = { decode: performance.now() - started };
  this.types = Array.from(new Set([].concat.apply([], this.sections.map(function (s) {
    return s.lanes.map(function (l) { return l.type; });
  })))).sort();
  this.markers = [];
  this.selected = -1;
  this.highlight = [];
  this.showReference = false;
  this.canvas = container.querySelector("canvas");  // on top: markers and highlight; takes the pointer
  this.ctx = this.canvas.getContext("2d");
  this.base = document.createElement("canvas");  // below: the lanes, redrawn only when the view changes
  this.base.className = "xc-base";
  this.base.setAttribute("aria-hidden", "true");
  this.canvas.parentNode.insertBefore(this.base, this.canvas);
  this.bctx = this.base.getContext("2d");
  this.tip = container.querySelector(".xc-tip");
  var b = data.bounds;
  this.bounds = b ? [b[0] - data.origin[0], b[1] - data.origin[1], b[2] - data.origin[0], b[3] - data.origin[1]]
                  : [-50, -50, 50, 50];
  this.cx = 0; this.cy = 0; this.scale = 1;
  this.resize();
  this.fit();
  this.bind();
};

var P = XC.MapView.prototype;

P.resize = function () {
  var r = this.canvas.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
  this.width = Math.max(1, r.width); this.height = Math.max(1, r.height); this.dpr = dpr;
  [this.canvas, this.base].forEach(function (c) { c.width = Math.round(r.width * dpr); c.height = Math.round(r.height * dpr); });
  this.overview = null;
  this.request("full");
};

P.fitScale = function (b) {
  var w = Math.max(b[2] - b[0], 1), h = Math.max(b[3] - b[1], 1);
  return Math.min(this.width / w, this.height / h) * 0.92;
};

/** Move the view; quick (during a gesture): a slow map is drawn from its last frame until the gesture rests. */
P.setView = function (cx, cy, scale, quick) {
  var lo = this.fitScale(this.bounds) * MIN_SCALE_FACTOR;
  this.scale = Math.max(lo, Math.min(MAX_SCALE, scale));
  this.cx = cx; this.cy = cy;
  this.container.dataset.centerX = (cx + this.origin[0]).toFixed(3);
  this.container.dataset.centerY = (cy + this.origin[1]).toFixed(3);
  this.container.dataset.scale = this.scale.toPrecision(4);
  this.request(quick ? "quick" : "full");
};

P.fit = function () {
  var b = this.bounds;
  this.setView((b[0] + b[2]) / 2, (b[1] + b[3]) / 2, this.fitScale(b));
};

/** Centre on world point (x, y), zoomed in to at least the focus scale. */
P.centerOn = function (x, y, scale) {
  this.setView(x - this.origin[0], y - this.origin[1], scale || Math.max(this.scale, FOCUS_SCALE));
};

P.fitBox = function (b) {
  this.setView((b[0] + b[2]) / 2, (b[1] + b[3]) / 2, Math.min(this.fitScale(b), 40));
};

P.toWorld = function (px, py) {
  return [this.cx + (px - this.width / 2) / this.scale, this.cy - (py - this.height / 2) / this.scale];
};
P.toScreen = function (x, y) {
  return [(x - this.cx) * this.scale + this.width / 2, this.height / 2 - (y - this.cy) * this.scale];
};

var RANK = { overlay: 1, quick: 2, full: 3 };

/** Draw at the next frame: "overlay" (markers, highlight), "quick" (a gesture: the lanes of a slow map from its last
 * frame, drawn in full once the gesture rests) or "full". */
P.request = function (mode) {
  var self = this;
  mode = mode || "full";
  if (mode === "quick" && !this.slow) mode = "full";
  if (mode === "quick") {
    window.clearTimeout(this.settle);
    this.settle = window.setTimeout(function () { self.request("full"); }, 200);
  }
  if (!this.mode || RANK[mode] > RANK[this.mode]) this.mode = mode;
  if (this.pending) return;
  this.pending = true;
  window.requestAnimationFrame(function () {
    var todo = self.mode;
    self.pending = false; self.mode = null;
    if (todo === "full") self.render(); else if (todo === "quick") self.renderQuick();
    self.renderOverlay();
  });
};

/** Lanes matching a finding's place: the lane of its section (by section start or s), or the whole road; lane 0 is
 * its line (drawn as the outline of a lane without width). */
P.lanesOf = function (road, sectionS, laneId, s) {
  var out = [];
  this.sections.forEach(function (sec) {
    if (sec.roadId !== road) return;
    if (sectionS !== null && Math.abs(sec.s0 - sectionS) > 1e-6) return;
    if (sectionS === null && s !== null && !(s >= sec.s[0] - 1e-6 && s <= sec.s[sec.n - 1] + 1e-6)) return;
    if (laneId === 0) { out.push({ sec: sec, id: 0, type: "centre line", inner: 1, outer: 1 }); return; }  // a line
    sec.lanes.forEach(function (lane) { if (laneId === null || lane.id === laneId) out.push(lane); });
  });
  return out;
};

P.lanesBox = function (lanes) {
  var b = [Infinity, Infinity, -Infinity, -Infinity];
  lanes.forEach(function (lane) {
    [lane.inner, lane.outer].forEach(function (k) {
      var X = lane.sec.xs[k], Y = lane.sec.ys[k];
      for (var j = 0; j < X.length; j++) {
        b[0] = Math.min(b[0], X[j]); b[1] = Math.min(b[1], Y[j]); b[2] = Math.max(b[2], X[j]); b[3] = Math.max(b[3], Y[j]);
      }
    });
  });
  return b;
};

P.setHighlight = function (lanes) { this.highlight = lanes; this.request("overlay"); };
P.setMarkers = function (markers) { this.markers = markers; this.request("overlay"); };
P.select = function (index) { this.selected = index; this.request("overlay"); };

P.bind = function () {
  var self = this, c = this.canvas, drag = null;
  c.addEventListener("pointerdown", function (e) {
    drag = { x: e.clientX, y: e.clientY, cx: self.cx, cy: self.cy, moved: false };
    c.setPointerCapture(e.pointerId);
  });
  c.addEventListener("pointermove", function (e) {
    if (drag) {
      var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      if (Math.abs(dx) + Math.abs(dy) > 3) drag.moved = true;
      if (drag.moved) self.setView(drag.cx - dx / self.scale, drag.cy + dy / self.scale, self.scale, true);
      self.tip.hidden = true;
      return;
    }
    self.hover(e);
  });
  c.addEventListener("pointerup", function (e) {
    var was = drag; drag = null;
    if (was && !was.moved) self.click(e);
  });
  c.addEventListener("pointerleave", function () { self.tip.hidden = true; });
  c.addEventListener("wheel", function (e) {
    e.preventDefault();
    var r = c.getBoundingClientRect();
    self.zoomAt(e.clientX - r.left, e.clientY - r.top, Math.exp(-e.deltaY * (e.deltaMode ? 0.05 : 0.0015)), true);
  }, { passive: false });
  c.addEventListener("dblclick", function (e) {
    var r = c.getBoundingClientRect();
    self.zoomAt(e.clientX - r.left, e.clientY - r.top, e.shiftKey ? 0.5 : 2);
  });
  c.addEventListener("keydown", function (e) {
    var step = 80 / self.scale, keys = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, step],
                                         ArrowDown: [0, -step] };
    if (keys[e.key]) { self.setView(self.cx + keys[e.key][0], self.cy + keys[e.key][1], self.scale); }
    else if (e.key === "+" || e.key === "=") self.zoomAt(self.width / 2, self.height / 2, 1.5);
    else if (e.key === "-") self.zoomAt(self.width / 2, self.height / 2, 1 / 1.5);
    else if (e.key === "0") self.fit();
    else return;
    e.preventDefault();
  });
  if (window.ResizeObserver) new ResizeObserver(function () { self.resize(); }).observe(c);
};

P.zoomAt = function (px, py, factor, quick) {
  var w = this.toWorld(px, py), scale = this.scale * factor;
  var lo = this.fitScale(this.bounds) * MIN_SCALE_FACTOR;
  scale = Math.max(lo, Math.min(MAX_SCALE, scale));
  this.setView(w[0] - (px - this.width / 2) / scale, w[1] + (py - this.height / 2) / scale, scale, quick);
};

P.markerAt = function (px, py) {
  var best = -1, bestD = 81;
  for (var i = 0; i < this.markers.length; i++) {
    var m = this.markers[i];
    if (m.hidden || (m.muted && m.index !== this.selected)) continue;
    var p = this.toScreen(m.x - this.origin[0], m.y - this.origin[1]), d = (p[0] - px) * (p[0] - px) + (p[1] - py) * (p[1] - py);
    if (d <= bestD) { bestD = d; best = i; }
  }
  return best;
};

P.click = function (e) {
  var r = this.canvas.getBoundingClientRect(), i = this.markerAt(e.clientX - r.left, e.clientY - r.top);
  if (i >= 0 && this.options.onMarker) this.options.onMarker(this.markers[i]);
};

P.hover = function (e) {
  var r = this.canvas.getBoundingClientRect(), px = e.clientX - r.left, py = e.clientY - r.top;
  var w = this.toWorld(px, py), hit = XC.hitLane(this.cells, w[0], w[1]), m = this.markerAt(px, py);
  var lines = [];
  if (m >= 0) lines.push(this.markers[m].label);
  if (hit) {
    var sec = hit.lane.sec;
    var named = sec.roadName && sec.roadName !== "Road " + sec.roadId;  // CARLA names every road "Road <id>"
    lines.push("road " + sec.roadId + (named ? " (" + sec.roadName + ")" : "") +
               (sec.junction !== null ? " · junction " + sec.junction : ""),
               "lane section " + sec.index + " (s " + sec.s0.toFixed(2) + ") · lane " + hit.lane.id + " · " + hit.lane.type,
               "s " + hit.s.toFixed(2) + " m");
  }
  lines.push("x " + (w[0] + this.origin[0]).toFixed(2) + "  y " + (w[1] + this.origin[1]).toFixed(2));
  this.tip.textContent = lines.join("\n");
  this.tip.hidden = false;
  this.tip.style.left = Math.min(px + 14, this.width - this.tip.offsetWidth - 4) + "px";
  this.tip.style.top = Math.min(py + 14, this.height - this.tip.offsetHeight - 4) + "px";
  this.hovered = hit ? hit.lane : null;
};
