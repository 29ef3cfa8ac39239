/* xodrcheck map view: drawing. Each cell keeps its paths per level of detail (world coordinates), so a pan only
 * refills cached paths under a new transform; the level follows the zoom (half a pixel of tolerance). */
var XC = window.XC || (window.XC = {});

function addLane(path, sec, lane, idx) {
  var X = sec.xs, Y = sec.ys, I = lane.inner, O = lane.outer, k;
  path.moveTo(X[I][idx[0]], Y[I][idx[0]]);
  for (k = 1; k < idx.length; k++) path.lineTo(X[I][idx[k]], Y[I][idx[k]]);
  for (k = idx.length - 1; k >= 0; k--) path.lineTo(X[O][idx[k]], Y[O][idx[k]]);
  path.closePath();
}

function addLine(path, X, Y, idx, from, to) {
  var started = false;
  for (var k = 0; k < idx.length; k++) {
    var j = idx[k];
    if (j < from) continue;
    if (!started) { path.moveTo(X[from], Y[from]); started = true; if (j === from) continue; }
    if (j >= to) break;
    path.lineTo(X[j], Y[j]);
  }
  if (started) path.lineTo(X[to], Y[to]);
}

/** A line shifted sideways by d metres (left of its direction for d > 0), between samples from and to. */
function shifted(X, Y, idx, from, to, d) {
  var keep = [from];
  idx.forEach(function (j) { if (j > from && j < to) keep.push(j); });
  keep.push(to);
  var sx = new Float64Array(X.length), sy = new Float64Array(Y.length);
  keep.forEach(function (j, k) {
    var a = keep[Math.max(k - 1, 0)], b = keep[Math.min(k + 1, keep.length - 1)];
    var tx = X[b] - X[a], ty = Y[b] - Y[a], L = Math.hypot(tx, ty) || 1;
    sx[j] = X[j] - d * ty / L; sy[j] = Y[j] + d * tx / L;
  });
  return [sx, sy, keep];
}

var MARK_STYLES = {  // mark type -> [dash pattern in metres per line (null: solid)]
  solid: [null], broken: [[3, 6]], "solid solid": [null, null], "solid broken": [null, [3, 6]],
  "broken solid": [[3, 6], null], "broken broken": [[3, 6], [3, 6]], "botts dots": [[0.15, 1.2]],
  curb: [null], edge: [null], grass: [null], custom: [null]
};

function markColor(mark) {
  if (mark.type === "grass") return "#5f9a4a";
  if (mark.type === "curb") return "#d8d8d8";
  return XC.MARK_COLORS[mark.color] || "#ffffff";
}

function addMarks(paths, sec, idx) {
  sec.marks.forEach(function (mark) {
    var dashes = MARK_STYLES[mark.type] || [null], width = mark.width || 0.12, X = sec.xs[mark.line], Y = sec.ys[mark.line];
    dashes.forEach(function (dash, k) {
      var key = markColor(mark) + "|" + (dash ? dash.join(",") : "") + "|" + width;
      var path = paths.get(key);
      if (!path) paths.set(key, (path = { path: new Path2D(), color: markColor(mark), dash: dash, width: width }));
      if (dashes.length === 1) { addLine(path.path, X, Y, idx, mark.start, mark.stop); return; }
      var sh = shifted(X, Y, idx, mark.start, mark.stop, (k ? -1 : 1) * width);
      addLine(path.path, sh[0], sh[1], sh[2], mark.start, mark.stop);
    });
  });
}

/** The outline of a whole section (leftmost to rightmost border): what a coarse level fills instead of its lanes. */
function addEnvelope(path, sec, idx) {
  var nr = sec.lanes.length - sec.nLeft;
  addLane(path, sec, { inner: sec.nLeft ? sec.nLeft + 1 : 1, outer: nr ? sec.xs.length - 1 : 1 }, idx);
}

/** Levels from this one on draw sections whole (lanes are a few pixels wide there), without borders or marks. */
XC.COARSE_LEVEL = 7;

/** The paths of a cell at a level of detail, built once. */
XC.cellPaths = function (cell, level) {
  var found = cell.paths[level];
  if (found) return found;
  var coarse = level >= XC.COARSE_LEVEL, points = 0;
  var p = { fills: new Map(), junction: new Path2D(), borders: new Path2D(), reference: new Path2D(), marks: new Map(),
            centre: new Path2D() };
  cell.sections.forEach(function (sec) {
    if (!sec.lanes.length) return;
    var idx = XC.lodIndices(sec, level);
    points += idx.length * (coarse ? 4 : 3 * sec.lanes.length + 2);
    addLine(p.reference, sec.xs[0], sec.ys[0], idx, 0, sec.n - 1);
    addLine(p.centre, sec.xs[1], sec.ys[1], idx, 0, sec.n - 1);
    if (coarse) {
      var path = p.fills.get("driving");
      if (!path) p.fills.set("driving", (path = new Path2D()));
      addEnvelope(path, sec, idx);
      if (sec.junction !== null) addEnvelope(p.junction, sec, idx);
      return;
    }
    sec.lanes.forEach(function (lane) {
      var path = p.fills.get(lane.type);
      if (!path) p.fills.set(lane.type, (path = new Path2D()));
      addLane(path, sec, lane, idx);
      if (sec.junction !== null) addLane(p.junction, sec, lane, idx);
    });
    for (var k = 2; k < sec.xs.length; k++) addLine(p.borders, sec.xs[k], sec.ys[k], idx, 0, sec.n - 1);
    addMarks(p.marks, sec, idx);
  });
  p.points = points;
  return (cell.paths[level] = p);
};

var P = XC.MapView.prototype;
var SLOW_POINTS = 30000;  // points drawn beyond which a gesture moves the last frame instead of drawing anew

P.worldTransform = function (ctx) {
  var s = this.scale * this.dpr;
  ctx.setTransform(s, 0, 0, -s, (this.width / 2 - this.cx * this.scale) * this.dpr,
                   (this.height / 2 + this.cy * this.scale) * this.dpr);
};

P.visibleCells = function () {
  var a = this.toWorld(0, this.height), b = this.toWorld(this.width, 0);
  return this.cells.filter(function (c) {
    return c.bbox[2] >= a[0] && c.bbox[0] <= b[0] && c.bbox[3] >= a[1] && c.bbox[1] <= b[1];
  });
};

P.level = function () {  // the level of detail whose tolerance (2^level cm) is at most half a pixel
  return Math.max(0, Math.min(14, Math.floor(Math.log2(50 / this.scale))));
};

/** The lanes, borders, marks and (optionally) reference lines of the visible cells, on the base canvas. */
P.render = function () {
  var ctx = this.bctx, px = 1 / this.scale, started = performance.now();
  var level = this.level();
  ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
  ctx.fillStyle = BACKGROUND;
  ctx.fillRect(0, 0, this.width, this.height);
  this.worldTransform(ctx);
  var cells = this.visibleCells().map(function (c) { return XC.cellPaths(c, level); });
  this.types.forEach(function (type) {
    ctx.fillStyle = XC.LANE_COLORS[type] || "#b0b0b0";
    cells.forEach(function (p) { var path = p.fills.get(type); if (path) ctx.fill(path); });
  });
  if (level >= XC.COARSE_LEVEL) {  // roads a few pixels wide: a hairline keeps every road visible
    ctx.strokeStyle = XC.LANE_COLORS.driving;
    ctx.lineWidth = 1.2 * px;
    cells.forEach(function (p) { ctx.stroke(p.centre); });
  }
  ctx.fillStyle = JUNCTION_TINT;
  cells.forEach(function (p) { ctx.fill(p.junction); });
  if (this.scale > 1.2) {
    ctx.strokeStyle = "rgba(255, 255, 255, 0.35)";
    ctx.lineWidth = px;
    cells.forEach(function (p) { ctx.stroke(p.borders); });
  }
  if (this.scale > 1.5) this.renderMarks(ctx, cells, px);
  if (this.showReference) {
    ctx.strokeStyle = "#c0308a"; ctx.lineWidth = 1.5 * px;
    cells.forEach(function (p) { ctx.stroke(p.reference); });
  }
  this.drawn = { cx: this.cx, cy: this.cy, scale: this.scale, width: this.width, height: this.height };
  this.frame = null;  // taken again when a gesture starts
  if (!this.overview && this.showsAll()) this.overview = this.snapshot();
  // drawing is measured by what it draws: canvas commands return before the pixels are made
  this.slow = cells.reduce(function (sum, p) { return sum + p.points; }, 0) > SLOW_POINTS;
  if (!this.container.dataset.ready) {
    this.container.dataset.ready = "true";
    this.timings.draw = performance.now() - started;
    this.timings.ready = performance.now();
  }
};

P.renderMarks = function (ctx, cells, px) {
  ctx.lineCap = "butt";
  cells.forEach(function (p) {
    p.marks.forEach(function (m) {
      ctx.strokeStyle = m.color;
      ctx.lineWidth = Math.max(m.width, px);
      ctx.setLineDash(m.dash || []);
      ctx.stroke(m.path);
    });
  });
  ctx.setLineDash([]);
};

P.showsAll = function () {
  var b = this.bounds, a = this.toWorld(0, this.height), c = this.toWorld(this.width, 0);
  return a[0] <= b[0] && a[1] <= b[1] && c[0] >= b[2] && c[1] >= b[3];
};

/** A copy of the base canvas with the view it shows. */
P.snapshot = function () {
  var copy = document.createElement("canvas");
  copy.width = this.base.width; copy.height = this.base.height;
  copy.getContext("2d").drawImage(this.base, 0, 0);
  copy.view = this.drawn;
  return copy;
};

P.drawFrame = function (image) {
  var v = image.view, k = this.scale / v.scale, d = this.dpr;
  var ox = this.width / 2 - k * v.width / 2 + (v.cx - this.cx) * this.scale;
  var oy = this.height / 2 - k * v.height / 2 - (v.cy - this.cy) * this.scale;
  this.bctx.setTransform(d * k, 0, 0, d * k, d * ox, d * oy);
  this.bctx.drawImage(image, 0, 0, v.width, v.height);
};

/** During a gesture on a slow map: the last full frame (and the overview around it), moved and scaled. */
P.renderQuick = function () {
  if (!this.frame) this.frame = this.snapshot();
  var ctx = this.bctx;
  ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
  ctx.fillStyle = BACKGROUND;
  ctx.fillRect(0, 0, this.width, this.height);
  if (this.overview) this.drawFrame(this.overview);
  this.drawFrame(this.frame);
};

/** The highlighted lanes and the finding markers, on the top canvas. */
P.renderOverlay = function () {
  var ctx = this.ctx;
  ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
  ctx.clearRect(0, 0, this.width, this.height);
  if (this.highlight.length) {
    var path = new Path2D(), level = this.level();
    this.highlight.forEach(function (lane) { addLane(path, lane.sec, lane, XC.lodIndices(lane.sec, level)); });
    this.worldTransform(ctx);
    ctx.fillStyle = "rgba(0, 200, 255, 0.35)";
    ctx.fill(path);
    ctx.strokeStyle = HIGHLIGHT;
    ctx.lineWidth = 3 / this.scale;
    ctx.stroke(path);
    ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
  }
  this.renderMarkers();
  if (this.options.onRender) this.options.onRender(this);
};

P.renderMarkers = function () {  // one path per severity: thousands of markers cost a few draw calls
  var ctx = this.ctx, self = this, chosen = null, paths = {};
  this.markers.forEach(function (m) {
    if (m.hidden) return;
    var p = self.toScreen(m.x - self.origin[0], m.y - self.origin[1]);
    if (p[0] < -10 || p[1] < -10 || p[0] > self.width + 10 || p[1] > self.height + 10) return;
    if (m.index === self.selected) { chosen = { p: p, m: m }; return; }  // drawn even when muted: it was chosen
    if (m.muted) return;
    var path = paths[m.severity] || (paths[m.severity] = new Path2D());
    var r = m.severity === "info" ? 4 : 5;
    path.moveTo(p[0] + r, p[1]);
    path.arc(p[0], p[1], r, 0, 2 * Math.PI);
  });
  ctx.lineWidth = 1.5;
  ctx.strokeStyle = "#ffffff";
  ["info", "warning", "error"].forEach(function (severity) {  // the worst on top
    if (!paths[severity]) return;
    ctx.fillStyle = XC.SEVERITY_COLORS[severity];
    ctx.fill(paths[severity]);
    ctx.stroke(paths[severity]);
  });
  if (!chosen) return;
  var p = chosen.p;
  ctx.beginPath(); ctx.arc(p[0], p[1], 7, 0, 2 * Math.PI);
  ctx.fillStyle = XC.SEVERITY_COLORS[chosen.m.severity] || "#888"; ctx.fill();
  ctx.lineWidth = 3; ctx.strokeStyle = "#111"; ctx.stroke();
  ctx.beginPath(); ctx.arc(p[0], p[1], 13, 0, 2 * Math.PI);
  ctx.lineWidth = 2; ctx.strokeStyle = HIGHLIGHT; ctx.stroke();
};
