/* xodrcheck map data: decoding (the format of xodrcheck/mapview/encode.py), level of detail and a spatial index. */
var XC = window.XC || (window.XC = {});

/** Decode a map description into sections with per-line Float64Array x/y (metres from data.origin). */
XC.decodeMap = function (data) {
  var text = atob(data.stream || "");
  var bytes = new Uint8Array(text.length);
  for (var i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
  var pos = 0;
  function next() {  // one zigzag varint; the usual small value without floating-point arithmetic
    var b = bytes[pos++];
    if (b < 128) return (b >>> 1) ^ -(b & 1);
    var v = b & 127, mul = 128;
    do { b = bytes[pos++]; v += (b & 127) * mul; mul *= 128; } while (b & 128);
    return v % 2 === 0 ? v / 2 : -(v + 1) / 2;
  }
  function lanes(flat) {
    var out = [];
    for (var k = 0; k < flat.length; k += 2) out.push({ id: flat[k], type: data.laneTypes[flat[k + 1]] });
    return out;
  }
  var total = 0, longest = 0;
  data.sections.forEach(function (rec) {
    total += rec[3] * (2 + (rec[4].length + rec[5].length) / 2);
    longest = Math.max(longest, rec[3]);
  });
  var X = new Float64Array(total), Y = new Float64Array(total), at = 0;  // every line's points, in metres
  var prev = [new Float64Array(longest), new Float64Array(longest)];
  var sections = data.sections.map(function (rec) {
    var n = rec[3], s = new Float64Array(n), acc = 0, j, k, c;
    for (j = 0; j < n; j++) { acc += next(); s[j] = rec[2] + acc / 100; }
    var left = lanes(rec[4]), right = lanes(rec[5]);
    var count = 2 + left.length + right.length, xs = [], ys = [];
    for (k = 0; k < count; k++) {
      var out = [X.subarray(at, at + n), Y.subarray(at, at + n)];
      for (c = 0; c < 2; c++) {
        var p = prev[c], o = out[c];
        acc = 0;
        for (j = 0; j < n; j++) { acc += next(); p[j] = acc + (k ? p[j] : 0); o[j] = p[j] / 100; }
      }
      xs.push(out[0]); ys.push(out[1]); at += n;
    }
    return XC.makeSection(data.roads[rec[0]], rec, s, xs, ys, left, right, data);
  });
  return sections;
};

/** A decoded section with its lanes (line indices of their borders), marks and bounding box. */
XC.makeSection = function (road, rec, s, xs, ys, left, right, data) {
  var sec = { roadId: road[0], junction: road[1], roadName: road[2], index: rec[1], s0: rec[2], s: s, xs: xs, ys: ys,
              n: s.length, lanes: [], marks: [], lod: {} };
  var nl = left.length;
  sec.nLeft = nl;
  left.forEach(function (lane, k) {
    sec.lanes.push({ sec: sec, id: lane.id, type: lane.type, inner: k ? k + 1 : 1, outer: k + 2 });
  });
  right.forEach(function (lane, k) {
    sec.lanes.push({ sec: sec, id: lane.id, type: lane.type, inner: k ? nl + k + 1 : 1, outer: nl + k + 2 });
  });
  var m = rec[6];
  for (var i = 0; i < m.length; i += 6) {
    sec.marks.push({ line: m[i], start: m[i + 1], stop: m[i + 2], type: data.markTypes[m[i + 3]],
                     color: data.markColors[m[i + 4]], width: m[i + 5] / 100 });
  }
  var x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (var k = 1; k < xs.length; k++) {
    for (var j = 0; j < sec.n; j++) {
      var x = xs[k][j], y = ys[k][j];
      if (x < x0) x0 = x; if (x > x1) x1 = x; if (y < y0) y0 = y; if (y > y1) y1 = y;
    }
  }
  sec.bbox = [x0, y0, x1, y1];
  sec.importance = XC.importance(sec);
  return sec;
};

/** Douglas-Peucker importance of each sample over all lines of a section: the largest distance (m) of any line's
 * point from its chord when the sample is split off, capped by its parent's. Samples with importance above a
 * tolerance are the Douglas-Peucker simplification at that tolerance (the ends are always kept). */
XC.importance = function (sec) {
  var n = sec.n, imp = new Float32Array(n), xs = sec.xs, ys = sec.ys, lines = xs.length;
  imp[0] = imp[n - 1] = Infinity;
  var stack = [0, n - 1, Infinity];
  while (stack.length) {
    var cap = stack.pop(), b = stack.pop(), a = stack.pop();
    if (b - a < 2) continue;
    var best = -1, bestD = -1;
    for (var i = a + 1; i < b; i++) {
      var d = 0;
      for (var k = 0; k < lines; k++) {
        var X = xs[k], Y = ys[k];
        var ax = X[a], ay = Y[a], dx = X[b] - ax, dy = Y[b] - ay, px = X[i] - ax, py = Y[i] - ay;
        var L2 = dx * dx + dy * dy, t = L2 > 0 ? Math.max(0, Math.min(1, (px * dx + py * dy) / L2)) : 0;
        var ex = px - t * dx, ey = py - t * dy, e = ex * ex + ey * ey;
        if (e > d) d = e;
      }
      if (d > bestD) { bestD = d; best = i; }
    }
    bestD = Math.min(Math.sqrt(bestD), cap);
    if (bestD < 1e-3) { for (var q = a + 1; q < b; q++) imp[q] = bestD; continue; }
    imp[best] = bestD;
    stack.push(a, best, bestD, best, b, bestD);
  }
  return imp;
};

/** Sample indices of a section kept at level k (tolerance 2^k cm), computed once per level. */
XC.lodIndices = function (sec, level) {
  var found = sec.lod[level];
  if (found) return found;
  var tol = Math.pow(2, level) / 100, out = [];
  for (var i = 0; i < sec.n; i++) if (sec.importance[i] > tol) out.push(i);
  return (sec.lod[level] = out);
};

/** Sections grouped in square cells (by the centre of their box), each cell with the union box of its sections. */
XC.buildCells = function (sections, size) {
  var byKey = new Map();
  sections.forEach(function (sec) {
    var b = sec.bbox, key = Math.floor((b[0] + b[2]) / 2 / size) + "," + Math.floor((b[1] + b[3]) / 2 / size);
    var cell = byKey.get(key);
    if (!cell) byKey.set(key, (cell = { sections: [], bbox: [Infinity, Infinity, -Infinity, -Infinity], paths: {} }));
    cell.sections.push(sec);
    cell.bbox = [Math.min(cell.bbox[0], b[0]), Math.min(cell.bbox[1], b[1]),
                 Math.max(cell.bbox[2], b[2]), Math.max(cell.bbox[3], b[3])];
  });
  return Array.from(byKey.values());
};

function inQuad(px, py, ax, ay, bx, by, cx, cy, dx, dy) {
  var inside = false, xs = [ax, bx, cx, dx], ys = [ay, by, cy, dy];
  for (var i = 0, j = 3; i < 4; j = i++) {
    if ((ys[i] > py) !== (ys[j] > py) && px < (xs[j] - xs[i]) * (py - ys[i]) / (ys[j] - ys[i]) + xs[i]) inside = !inside;
  }
  return inside;
}

/** The lane under a point (metres from the origin) and the s there, or null. */
XC.hitLane = function (cells, x, y) {
  for (var c = 0; c < cells.length; c++) {
    var cb = cells[c].bbox;
    if (x < cb[0] || x > cb[2] || y < cb[1] || y > cb[3]) continue;
    var secs = cells[c].sections;
    for (var q = secs.length - 1; q >= 0; q--) {
      var sec = secs[q], b = sec.bbox;
      if (x < b[0] || x > b[2] || y < b[1] || y > b[3]) continue;
      for (var l = 0; l < sec.lanes.length; l++) {
        var lane = sec.lanes[l], I = lane.inner, O = lane.outer, X = sec.xs, Y = sec.ys;
        for (var j = 0; j + 1 < sec.n; j++) {
          if (inQuad(x, y, X[I][j], Y[I][j], X[I][j + 1], Y[I][j + 1], X[O][j + 1], Y[O][j + 1], X[O][j], Y[O][j])) {
            var mx = (X[I][j] + X[O][j]) / 2, my = (Y[I][j] + Y[O][j]) / 2;
            var nx = (X[I][j + 1] + X[O][j + 1]) / 2 - mx, ny = (Y[I][j + 1] + Y[O][j + 1]) / 2 - my;
            var L2 = nx * nx + ny * ny, t = L2 > 0 ? ((x - mx) * nx + (y - my) * ny) / L2 : 0;
            t = Math.max(0, Math.min(1, t));
            return { lane: lane, s: sec.s[j] + t * (sec.s[j + 1] - sec.s[j]) };
          }
        }
      }
    }
  }
  return null;
};
