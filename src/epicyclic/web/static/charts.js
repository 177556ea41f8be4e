// epicyclic serve: the charts the browser draws from the data the server sends with the results
// (epicyclic/web/charts.py: the speed plan, the speed chart across gears, the torques, the powers).
// Drawn with Chart.js 3.9.1 (chart.min.js beside this file, MIT; see chart.NOTICE), only once a chart is on
// screen (a hidden tab draws nothing); the values under the pointer, a box dragged to zoom, a double-click
// to zoom out.  No inline script, no eval: the data is a JSON attribute (data-chart) of the picture's body.
"use strict";

(function () {
  if (!window.Chart) { return; }
  var FONT = 12, SMALL = 11;  // px: every text of a chart at least 11 px on the screen
  Chart.defaults.font.size = FONT;
  Chart.defaults.font.family = 'system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif';
  Chart.defaults.color = "#1d2330";
  Chart.defaults.animation = false;
  Chart.defaults.maintainAspectRatio = false;
  var EVENTS = ["mousemove", "mouseout", "click", "touchstart", "touchmove", "mousedown", "mouseup", "dblclick"];
  var live = [];  // every chart drawn: destroyed once its canvas has left the page

  // a number as the tables print it: 4 significant digits, no -0, exponent only for very large or small
  function fmt(value, digits) {
    if (value === null || value === undefined || !isFinite(value)) { return "—"; }
    if (value === 0) { return "0"; }
    var size = Math.abs(value);
    if (size >= 1e6 || size < 1e-4) { return value.toExponential((digits || 4) - 1); }
    return String(Number(value.toPrecision(digits || 4)));
  }

  function title(text) { return { display: !!text, text: text, font: { size: FONT + 1, weight: "600" } }; }
  function axis(spec, extra) {
    var options = { title: { display: !!spec.title, text: spec.title, font: { size: FONT } },
                    ticks: { font: { size: FONT } },
                    grid: { color: function (c) { return c.tick && c.tick.value === 0 ? "#000" : "rgba(0,0,0,.09)"; } } };
    return Object.assign(options, extra || {});
  }

  // ---- zoom: drag a box (both axes; a category axis zooms by whole categories), double-click: back
  function zoomTo(chart, box) {
    ["x", "y"].forEach(function (id) {
      var scale = chart.scales[id], along = id === "x" ? [box.x0, box.x1] : [box.y0, box.y1];
      if (!scale || Math.abs(along[1] - along[0]) < 8) { return; }
      var a = scale.getValueForPixel(along[0]), b = scale.getValueForPixel(along[1]);
      var low = Math.min(a, b), high = Math.max(a, b);
      if (scale.type === "category") { low = Math.ceil(low - 0.5); high = Math.floor(high + 0.5); if (high < low) { return; } }
      chart.options.scales[id].min = low;
      chart.options.scales[id].max = high;
    });
    chart.update("none");
  }
  function zoomHome(chart) {
    var home = chart.$home || {};
    ["x", "y"].forEach(function (id) {
      if (home[id]) { chart.options.scales[id].min = home[id][0]; chart.options.scales[id].max = home[id][1]; }
      else { delete chart.options.scales[id].min; delete chart.options.scales[id].max; }
    });
    chart.update("none");
  }
  var boxZoom = {
    id: "boxzoom",
    afterEvent: function (chart, args) {
      var e = args.event, box = chart.$box;
      if (args.replay) { return; }  // Chart.js replays the last event after an update: not a new click
      if (e.type === "mousedown") { chart.$box = { x0: e.x, y0: e.y, x1: e.x, y1: e.y }; }
      else if (e.type === "mousemove" && box) { box.x1 = e.x; box.y1 = e.y; args.changed = true; }
      else if (e.type === "mouseup" && box) { chart.$box = null; zoomTo(chart, box); args.changed = true; }
      else if (e.type === "mouseout") { chart.$box = null; args.changed = true; }
      else if (e.type === "dblclick") { zoomHome(chart); }
    },
    afterDraw: function (chart) {
      var box = chart.$box, c = chart.ctx;
      if (!box || (Math.abs(box.x1 - box.x0) < 4 && Math.abs(box.y1 - box.y0) < 4)) { return; }
      c.save();
      c.fillStyle = "rgba(43,95,179,.12)";
      c.strokeStyle = "#2b5fb3";
      c.fillRect(box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
      c.strokeRect(box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
      c.restore();
    }
  };

  // ---- the gear shown: a band behind its category
  var band = {
    id: "band",
    beforeDatasetsDraw: function (chart, args, options) {
      var x = chart.scales.x, area = chart.chartArea;
      if (options.index === null || options.index === undefined || options.index < x.min || options.index > x.max) { return; }
      var width = 0.8 * x.width / Math.max(1, x.max - x.min + 1), centre = x.getPixelForValue(options.index);
      chart.ctx.save();
      chart.ctx.fillStyle = "rgba(255,214,107,.45)";
      chart.ctx.fillRect(centre - width / 2, area.top, width, area.bottom - area.top);
      chart.ctx.restore();
    }
  };

  // ---- texts beside points (the speed plan's mesh points) and above bars (the torques)
  function text(c, words, x, y, align, baseline) {
    c.font = SMALL + "px " + Chart.defaults.font.family;
    c.textAlign = align; c.textBaseline = baseline;
    c.lineWidth = 3; c.strokeStyle = "rgba(255,255,255,.9)"; c.strokeText(words, x, y);
    c.fillStyle = "#1d2330"; c.fillText(words, x, y);
  }
  var labels = {
    id: "labels",
    afterDatasetsDraw: function (chart) {
      var c = chart.ctx, area = chart.chartArea;
      c.save();
      c.beginPath(); c.rect(area.left, area.top, area.right - area.left, area.bottom - area.top); c.clip();
      chart.data.datasets.forEach(function (dataset, d) {
        var meta = chart.getDatasetMeta(d);
        if (meta.hidden) { return; }
        meta.data.forEach(function (element, i) {
          if (dataset.pointLabels) { text(c, dataset.pointLabels[i], element.x + 7, element.y - 3, "left", "bottom"); }
          if (dataset.valueLabels && dataset.data[i] !== null) {
            var up = dataset.data[i] >= 0;
            text(c, fmt(dataset.data[i]), element.x, element.y + (up ? -3 : 3), "center", up ? "bottom" : "top");
          }
        });
      });
      c.restore();
    }
  };

  // ---- powers as areas: rectangles spanning a speed (x) and a torque (y), found under the pointer
  function rectPixels(chart, r) {
    var x = chart.scales.x, y = chart.scales.y;
    var left = x.getPixelForValue(r.x0), right = x.getPixelForValue(r.x1);
    var top = y.getPixelForValue(r.y1), bottom = y.getPixelForValue(r.y0);
    return { left: Math.min(left, right), right: Math.max(left, right), top: Math.min(top, bottom), bottom: Math.max(top, bottom) };
  }
  Chart.Interaction.modes.rect = function (chart, e) {
    var found = [];
    chart.data.datasets.forEach(function (dataset, d) {
      var meta = chart.getDatasetMeta(d);
      if (!dataset.rects || meta.hidden) { return; }
      dataset.rects.forEach(function (r, i) {
        var p = rectPixels(chart, r);
        if (e.x >= p.left - 3 && e.x <= p.right + 3 && e.y >= p.top - 1 && e.y <= p.bottom + 1) {
          found.push({ element: meta.data[i], datasetIndex: d, index: i });
        }
      });
    });
    return found;
  };
  var rects = {
    id: "rects",
    beforeDatasetsDraw: function (chart, args, options) {
      var c = chart.ctx, area = chart.chartArea;
      c.save();
      c.beginPath(); c.rect(area.left, area.top, area.right - area.left, area.bottom - area.top); c.clip();
      chart.data.datasets.forEach(function (dataset, d) {
        if (!dataset.rects || chart.getDatasetMeta(d).hidden) { return; }
        dataset.rects.forEach(function (r) {
          var p = rectPixels(chart, r), loss = r.role === "loss";
          if (r.friction) {
            c.globalAlpha = 0.85;
            c.fillStyle = options.roles[r.role].colour;
            c.fillRect(p.left, p.top, p.right - p.left, p.bottom - p.top);
            c.globalAlpha = 1;
            c.setLineDash([]);
            c.lineWidth = loss ? 3 : 1;
            c.strokeStyle = loss ? "#000" : "#333";
          } else {
            c.setLineDash([6, 4]);
            c.lineWidth = 1.5;
            c.strokeStyle = "#666";
          }
          c.strokeRect(p.left, p.top, p.right - p.left, p.bottom - p.top);
        });
      });
      c.restore();
    },
    afterDatasetsDraw: function (chart) {
      var c = chart.ctx;
      c.save();
      chart.data.datasets.forEach(function (dataset, d) {
        if (!dataset.rects || chart.getDatasetMeta(d).hidden) { return; }
        dataset.rects.forEach(function (r) {
          var p = rectPixels(chart, r);
          if (!r.friction || p.right - p.left < 2) { return; }  // a shaft at rest carries no power: no label
          var words = r.label + ": " + r.power, area = chart.chartArea;
          c.font = SMALL + "px " + Chart.defaults.font.family;
          var half = c.measureText(words).width / 2 + 4;  // inside the panel, beside the rectangle's middle
          var x = Math.max(Math.min((p.left + p.right) / 2, area.right - half), area.left + half);
          var y = r.role === "loss" ? p.top - 3 : (p.top + p.bottom) / 2;
          text(c, words, x, y, "center", r.role === "loss" ? "bottom" : "middle");
        });
      });
      c.restore();
    }
  };

  // ---- one panel of a chart as a Chart.js configuration
  function tooltip(extra) {
    return Object.assign({ titleFont: { size: FONT }, bodyFont: { size: FONT }, padding: 8 }, extra || {});
  }
  var PANELS = {
    line: function (panel) {
      return {
        type: "line",
        data: { labels: panel.x.labels, datasets: panel.series.map(function (s) {
          return { label: s.name, data: s.values, borderColor: s.colour, backgroundColor: s.colour,
                   borderWidth: s.bold ? 3.5 : 1.6, pointRadius: 3.5, pointHoverRadius: 6, spanGaps: false };
        }) },
        options: {
          interaction: { mode: "index", intersect: false },
          scales: { x: axis(panel.x, { offset: true, ticks: { autoSkip: false, maxRotation: 0, font: { size: FONT } } }),
                    y: axis(panel.y, { grace: "5%" }) },
          plugins: {
            band: { index: panel.highlight },
            tooltip: tooltip({
              filter: function (item) { return item.parsed.y !== null && !isNaN(item.parsed.y); },
              itemSort: function (a, b) { return b.parsed.y - a.parsed.y; },
              callbacks: {
                title: function (items) {
                  if (!items.length) { return ""; }
                  var label = panel.x.labels[items[0].dataIndex];
                  return "gear " + label[0] + (label.length > 1 ? " (" + label.slice(1).join(" + ") + " engaged)" : "");
                },
                label: function (item) { return item.dataset.label + ": " + fmt(item.parsed.y) + " " + panel.y.unit; }
              } })
          }
        },
        plugins: [band]
      };
    },
    bar: function (panel, spec) {
      var roles = spec.roles, used = [];
      panel.bars.forEach(function (b) { if (used.indexOf(b.role) < 0) { used.push(b.role); } });
      var withIdeal = panel.bars.some(function (b) { return b.ideal !== null; });
      var datasets = [{ label: "with friction", data: panel.bars.map(function (b) { return b.actual; }),
                        backgroundColor: panel.bars.map(function (b) { return roles[b.role].colour; }),
                        borderColor: "#333", borderWidth: 1, valueLabels: true }];
      if (withIdeal) {
        datasets.unshift({ label: "without friction", data: panel.bars.map(function (b) { return b.ideal; }),
                           backgroundColor: "rgba(0,0,0,.03)", borderColor: "#777", borderWidth: 1.5 });
      }
      return {
        type: "bar",
        data: { labels: panel.bars.map(function (b) { return b.label; }), datasets: datasets },
        options: {
          interaction: { mode: "index", intersect: false },
          scales: { x: axis(panel.x, { ticks: { autoSkip: false, maxRotation: 0, font: { size: FONT } } }),
                    y: axis(panel.y, { grace: "12%" }) },
          plugins: {
            legend: { onClick: function () {}, labels: { generateLabels: function () {
              var items = withIdeal ? [{ text: "without friction (outline)", fillStyle: "rgba(0,0,0,.03)", strokeStyle: "#777", lineWidth: 1.5 }] : [];
              return items.concat(used.map(function (role) {
                return { text: roles[role].label + (withIdeal ? ", with friction" : ""), fillStyle: roles[role].colour, strokeStyle: "#333", lineWidth: 1 };
              }));
            } } },
            tooltip: tooltip({ callbacks: {
              title: function (items) { return items.length ? [].concat(panel.bars[items[0].dataIndex].label).join(" ") : ""; },
              label: function (item) { return item.dataset.label + ": " + fmt(item.parsed.y) + " " + panel.y.unit; }
            } })
          }
        },
        plugins: [labels]
      };
    },
    xy: function (panel) {
      return {
        type: "scatter",
        data: { datasets: panel.series.map(function (s) {
          return { label: s.name, data: s.points.map(function (p) { return { x: p[0], y: p[1] }; }),
                   showLine: s.width > 0, borderColor: s.colour, backgroundColor: s.width > 0 ? s.colour : "#fff",
                   borderWidth: s.width > 0 ? s.width : 1.5, pointRadius: s.width > 0 ? 0 : 5, pointHoverRadius: 7,
                   pointLabels: s.point_labels, legendHidden: s.legend === false };
        }) },
        options: {
          interaction: { mode: "nearest", intersect: false },
          scales: { x: axis(panel.x, { type: "linear", grace: "12%" }), y: axis(panel.y, { type: "linear", grace: "6%" }) },
          plugins: {
            legend: { labels: { filter: function (item, data) { return !data.datasets[item.datasetIndex].legendHidden; } } },
            tooltip: tooltip({ callbacks: { label: function (item) {
              var name = item.dataset.pointLabels ? item.dataset.pointLabels[item.dataIndex] : item.dataset.label;
              return name + ": r = " + fmt(item.parsed.y) + " " + panel.y.unit + ", v = " + fmt(item.parsed.x) + " " + panel.x.unit;
            } } })
          }
        },
        plugins: [labels]
      };
    },
    rects: function (panel, spec) {
      var xs = [0], ys = [0], used = [];
      panel.rects.forEach(function (r) {
        xs.push(r.x0, r.x1); ys.push(r.y0, r.y1);
        if (r.friction && used.indexOf(r.role) < 0) { used.push(r.role); }
      });
      var dx = (Math.max.apply(null, xs) - Math.min.apply(null, xs)) || 1, dy = (Math.max.apply(null, ys) - Math.min.apply(null, ys)) || 1;
      var home = { x: [Math.min.apply(null, xs) - 0.05 * dx, Math.max.apply(null, xs) + 0.05 * dx],
                   y: [Math.min.apply(null, ys), Math.max.apply(null, ys) + 0.12 * dy] };
      var groups = [false, true].map(function (friction) {
        var mine = panel.rects.filter(function (r) { return r.friction === friction; });
        return { label: friction ? "with friction" : "without friction", rects: mine, pointRadius: 0,
                 data: mine.map(function (r) { return { x: (r.x0 + r.x1) / 2, y: (r.y0 + r.y1) / 2 }; }) };
      }).filter(function (g) { return g.rects.length; });
      return {
        type: "scatter",
        data: { datasets: groups },
        options: {
          interaction: { mode: "rect", intersect: true },
          scales: { x: axis(panel.x, { type: "linear", suggestedMin: home.x[0], suggestedMax: home.x[1] }),
                    y: axis(panel.y, { type: "linear", suggestedMin: home.y[0], suggestedMax: home.y[1] }) },
          plugins: {
            rects: { roles: spec.roles },
            legend: { onClick: function () {}, labels: { generateLabels: function () {
              return used.map(function (role) { return { text: spec.roles[role].label, fillStyle: spec.roles[role].colour, strokeStyle: "#333", lineWidth: role === "loss" ? 3 : 1 }; })
                .concat(groups.length > 1 ? [{ text: "without friction (dashed outline)", fillStyle: "#fff", strokeStyle: "#666", lineWidth: 1.5, lineDash: [6, 4] }] : []);
            } } },
            tooltip: tooltip({ callbacks: {
              title: function () { return ""; },
              label: function (item) {
                var r = item.dataset.rects[item.dataIndex];
                return r.label + " (" + item.dataset.label + "): " + r.power + " = " + r.speed + " × " + r.torque;
              } } })
          }
        },
        plugins: [rects]
      };
    }
  };

  // ---- a chart (title, notes, panels) into an element
  function draw(into, spec, tall) {
    var heading = document.createElement("p");
    heading.className = "chart-title";
    heading.textContent = spec.title;
    var grid = document.createElement("div");
    grid.className = "chart-grid chart-" + spec.kind;
    var made = [];
    spec.panels.forEach(function (panel) {
      var box = document.createElement("div"), canvas = document.createElement("canvas");
      box.className = "chart-panel";
      if (tall) { box.style.height = "min(70vh, 560px)"; }
      canvas.setAttribute("role", "img");
      canvas.setAttribute("aria-label", panel.title);
      box.appendChild(canvas);
      grid.appendChild(box);
      var config = PANELS[panel.type](panel, spec);
      config.options.events = EVENTS;
      config.options.plugins = Object.assign({ title: title(panel.title), legend: {} }, config.options.plugins);
      config.options.plugins.legend = Object.assign({ position: "bottom", labels: {} }, config.options.plugins.legend);
      config.options.plugins.legend.labels = Object.assign({ font: { size: FONT }, boxWidth: 16 }, config.options.plugins.legend.labels);
      config.plugins = (config.plugins || []).concat([boxZoom]);
      made.push([canvas, config]);
    });
    var notes = spec.notes.map(function (words) {
      var note = document.createElement("p");
      note.className = "chart-note";
      note.textContent = words;
      return note;
    });
    into.replaceChildren.apply(into, [heading].concat(notes, [grid]));
    return made.map(function (pair) {
      var chart = new Chart(pair[0], pair[1]);
      chart.$home = pair[1].home;
      live.push(chart);
      return chart;
    });
  }

  // one chart at a time, each in a task of its own, so that the page's requests for the other pictures go
  // out and their answers are shown in between; how long each took is kept (the benchmark reads it)
  var queue = [], timings = [];
  function drawBody(body) {
    if (body.hasAttribute("data-drawn") || !body.isConnected) { return; }
    var start = performance.now();
    draw(body, JSON.parse(body.getAttribute("data-chart")), false);
    body.setAttribute("data-drawn", "");
    timings.push([body.getAttribute("data-chart-kind"), performance.now() - start]);
    if (timings.length > 100) { timings.shift(); }
  }
  function drawNext() {
    if (!queue.length) { return; }
    drawBody(queue.shift());
    if (queue.length) { setTimeout(drawNext, 0); }
  }
  function later(body) {
    queue.push(body);
    if (queue.length === 1) { setTimeout(drawNext, 0); }
  }

  // ---- drawn once on screen (a hidden tab draws nothing until it is shown)
  var seen = window.IntersectionObserver ? new IntersectionObserver(function (entries) {
    entries.forEach(function (entry) {
      if (entry.isIntersecting) { seen.unobserve(entry.target); later(entry.target); }
    });
  }, { rootMargin: "200px" }) : null;

  function bind() {
    live = live.filter(function (chart) {
      if (chart.canvas && chart.canvas.isConnected) { return true; }
      chart.destroy();
      return false;
    });
    document.querySelectorAll(".chart-body[data-chart]:not([data-bound])").forEach(function (body) {
      body.setAttribute("data-bound", "");
      if (seen) { seen.observe(body); } else { drawBody(body); }
    });
  }
  document.addEventListener("htmx:afterSettle", bind);
  document.addEventListener("DOMContentLoaded", bind);

  // ---- the chart at the full width of the window (app.js's "enlarge" for a chart)
  function enlarge(figure, into) {
    var body = figure.querySelector(".chart-body[data-chart]");
    if (!body) { return false; }
    draw(into, JSON.parse(body.getAttribute("data-chart")), true);
    return true;
  }
  document.addEventListener("close", function (event) {
    if (event.target.id === "zoom") { setTimeout(bind, 0); }  // the dialog's charts go with its content
  }, true);

  window.epicyclicCharts = { enlarge: enlarge, fmt: fmt, timings: timings };
})();
