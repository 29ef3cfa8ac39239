/* xodrcheck map view: the lane graph the page carries (xodrcheck/mapview/routes.py). Lanes no route reaches are
 * shaded; with "route" on, a click on a lane starts a route and a second click ends it: the shortest way along the
 * lanes (links and the lane changes the road marks allow) is drawn and measured on the lane centres, whole lanes from
 * the first to the last. The map element carries the result: data-route-found, data-route-length (m),
 * data-route-lanes, and data-unreachable (how many lanes are shaded). */
var XC = window.XC || (window.XC = {});

var ROUTE_FILL = "rgba(30, 170, 80, 0.55)", ROUTE_EDGE = "#148a3c", UNREACHED_FILL = "rgba(215, 38, 61, 0.38)";
var LANE_CHANGE_COST = 1;  // metres: of two routes of one length, the one with fewer lane changes

function laneLength(lane) {
  if (lane.length !== undefined) return lane.length;
  var sec = lane.sec, I = lane.inner, O = lane.outer, total = 0;
  for (var j = 0; j + 1 < sec.n; j++) {
    var dx = (sec.xs[I][j + 1] + sec.xs[O][j + 1] - sec.xs[I][j] - sec.xs[O][j]) / 2;
    var dy = (sec.ys[I][j + 1] + sec.ys[O][j + 1] - sec.ys[I][j] - sec.ys[O][j]) / 2;
    total += Math.sqrt(dx * dx + dy * dy);
  }
  return (lane.length = total);
}

/** A binary heap of [cost, node] pairs, cheapest first. */
function Heap() { this.items = []; }
Heap.prototype.push = function (item) {
  var a = this.items, i = a.length;
  a.push(item);
  while (i > 0) {
    var p = (i - 1) >> 1;
    if (a[p][0] <= a[i][0]) break;
    var t = a[p]; a[p] = a[i]; a[i] = t; i = p;
  }
};
Heap.prototype.pop = function () {
  var a = this.items, top = a[0], last = a.pop();
  if (a.length) {
    a[0] = last;
    for (var i = 0; ;) {
      var l = 2 * i + 1, r = l + 1, m = i;
      if (l < a.length && a[l][0] < a[m][0]) m = l;
      if (r < a.length && a[r][0] < a[m][0]) m = r;
      if (m === i) break;
      var t = a[m]; a[m] = a[i]; a[i] = t; i = m;
    }
  }
  return top;
};

XC.LaneGraph = function (view, data) {
  var g = data.graph, byKey = {}, self = this;
  view.sections.forEach(function (sec) {
    sec.lanes.forEach(function (lane) { byKey[sec.roadId + "/" + sec.index + "/" + lane.id] = lane; });
  });
  this.lanes = [];  // per node: the drawn lane (null when not drawn)
  for (var k = 0; k < g.nodes.length; k += 4) {
    var road = data.roads[g.nodes[k]][0];
    this.lanes.push(byKey[road + "/" + g.nodes[k + 1] + "/" + g.nodes[k + 2]] || null);
  }
  this.out = this.lanes.map(function () { return []; });
  for (var e = 0; e < g.edges.length; e += 3) this.out[g.edges[e]].push([g.edges[e + 1], g.edges[e + 2]]);
  this.unreached = g.unreached.map(function (i) { return self.lanes[i]; }).filter(Boolean);
};

/** The nodes of a drawn lane (two for a lane driven both ways). */
XC.LaneGraph.prototype.nodesOf = function (lane) {
  var out = [];
  this.lanes.forEach(function (l, i) { if (l === lane) out.push(i); });
  return out;
};

/** The shortest route from lane a to lane b as a list of nodes (null when there is none). A link costs the length of
 * the lane it leaves, a lane change one metre. */
XC.LaneGraph.prototype.route = function (a, b) {
  var self = this, goal = {}, dist = {}, prev = {}, heap = new Heap();
  this.nodesOf(b).forEach(function (i) { goal[i] = true; });
  this.nodesOf(a).forEach(function (i) { dist[i] = 0; heap.push([0, i]); });
  while (heap.items.length) {
    var top = heap.pop(), d = top[0], u = top[1];
    if (d > dist[u]) continue;
    if (goal[u]) {
      var path = [u];
      while (prev[path[0]] !== undefined) path.unshift(prev[path[0]]);
      return path;
    }
    var here = self.lanes[u] ? laneLength(self.lanes[u]) : 0;
    self.out[u].forEach(function (edge) {
      var v = edge[0], cost = d + (edge[1] === 1 ? LANE_CHANGE_COST : here) + 1e-6;
      if (dist[v] === undefined || cost < dist[v]) { dist[v] = cost; prev[v] = u; heap.push([cost, v]); }
    });
  }
  return null;
};

XC.attachRoutes = function (view, data) {
  if (!data.graph) return;
  var graph = new XC.LaneGraph(view, data), box = view.container, tools = box.querySelector(".xc-tools");
  var state = { on: false, shade: true, from: null, to: null, path: null };
  box.dataset.unreachable = String(graph.unreached.length);
  var status = document.createElement("div");
  status.className = "xc-route-status";
  status.hidden = true;
  box.appendChild(status);
  function toggle(name, text, checked, onChange) {
    var label = document.createElement("label"), input = document.createElement("input");
    input.type = "checkbox"; input.dataset.tool = name; input.checked = checked;
    input.addEventListener("change", function () { onChange(input.checked); view.request("overlay"); });
    label.appendChild(input); label.appendChild(document.createTextNode(" " + text));
    if (tools) tools.appendChild(label);
  }
  toggle("route", "route", false, function (on) {
    state.on = on; state.from = state.to = state.path = null;
    status.hidden = !on;
    status.textContent = "click the lane to start from";
    box.dataset.routeFound = ""; box.dataset.routeLength = ""; box.dataset.routeLanes = "";
  });
  if (graph.unreached.length) toggle("unreachable", "unreachable lanes (" + graph.unreached.length + ")", true,
                                     function (on) { state.shade = on; });
  var down = null;
  view.canvas.addEventListener("pointerdown", function (e) { down = [e.clientX, e.clientY]; });
  view.canvas.addEventListener("pointerup", function (e) {
    if (!state.on || !down || Math.abs(e.clientX - down[0]) + Math.abs(e.clientY - down[1]) > 3) return;
    var r = view.canvas.getBoundingClientRect(), w = view.toWorld(e.clientX - r.left, e.clientY - r.top);
    var hit = XC.hitLane(view.cells, w[0], w[1]);
    if (!hit) return;
    if (!graph.nodesOf(hit.lane).length) {
      status.textContent = "road " + hit.lane.sec.roadId + " lane " + hit.lane.id + " (" + hit.lane.type +
                           ") is no lane of the graph: pick a drivable lane";
      return;
    }
    if (!state.from || state.to) {
      state.from = hit.lane; state.to = null; state.path = null;
      status.textContent = "from road " + hit.lane.sec.roadId + " lane " + hit.lane.id + ": click the lane to go to";
    } else {
      state.to = hit.lane;
      state.path = graph.route(state.from, state.to);
      var lanes = state.path ? state.path.map(function (i) { return graph.lanes[i]; }).filter(Boolean) : [];
      var length = lanes.reduce(function (sum, lane, k) {
        return sum + (k > 0 && lane.sec === lanes[k - 1].sec ? 0 : laneLength(lane));  // a lane change: on the way
      }, 0);
      box.dataset.routeFound = state.path ? "true" : "false";
      box.dataset.routeLength = state.path ? length.toFixed(1) : "";
      box.dataset.routeLanes = state.path ? String(lanes.length) : "";
      status.textContent = state.path
        ? "route: " + length.toFixed(1) + " m over " + lanes.length + " lanes"
        : "no route from road " + state.from.sec.roadId + " lane " + state.from.id + " to road " +
          state.to.sec.roadId + " lane " + state.to.id;
    }
    view.request("overlay");
  });
  var before = view.options.onRender;
  view.options.onRender = function (v) {
    var ctx = v.ctx, level = v.level(), painted = false;
    function fill(lanes, style, edge) {
      if (!lanes.length) return;
      var path = new Path2D();
      lanes.forEach(function (lane) { addLane(path, lane.sec, lane, XC.lodIndices(lane.sec, level)); });
      v.worldTransform(ctx);
      ctx.fillStyle = style; ctx.fill(path);
      if (edge) { ctx.strokeStyle = edge; ctx.lineWidth = 2.5 / v.scale; ctx.stroke(path); }
      ctx.setTransform(v.dpr, 0, 0, v.dpr, 0, 0);
      painted = true;
    }
    if (state.shade) fill(graph.unreached, UNREACHED_FILL);
    if (state.on) {
      var route = state.path ? state.path.map(function (i) { return graph.lanes[i]; }).filter(Boolean) : [];
      fill(route, ROUTE_FILL, ROUTE_EDGE);
      fill([state.from, state.to].filter(Boolean), "rgba(0, 0, 0, 0)", "#111111");
    }
    if (painted) v.renderMarkers();  // the findings stay on top
    if (before) before(v);
  };
  view.request("overlay");
};
