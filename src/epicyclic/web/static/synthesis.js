// epicyclic serve: the Synthesis tab (templates/synthesis.html).  A search runs as one request, the answer of
// which is its ranked candidates; while it runs, its progress is polled and Cancel stops it (the candidates
// found by then come as its answer).  "Open in editor" opens a candidate's train file as a new document.
"use strict";

(function () {
  function byId(id) { return document.getElementById(id); }
  var polling = null;

  function newId() {
    return (window.crypto && crypto.randomUUID) ? crypto.randomUUID()
      : String(Math.random()).slice(2) + "-" + Date.now();
  }

  function poll() {
    var id = byId("synth-id");
    if (!id || !id.value) { return; }
    htmx.ajax("POST", "/synthesis/progress", { target: "#synthesis-progress", swap: "innerHTML",
                                               values: { synth_id: id.value } });
  }

  function running(on) {
    var cancel = byId("synthesis-cancel");
    if (cancel) { cancel.disabled = !on; }
    clearInterval(polling);
    polling = on ? setInterval(poll, 500) : null;
    if (!on) { byId("synthesis-progress").replaceChildren(); }
  }

  // the search's id goes with its start; progress and Cancel name it
  document.addEventListener("htmx:configRequest", function (event) {
    if (event.detail.path === "/synthesis/start") {
      var id = newId();
      byId("synth-id").value = id;
      event.detail.parameters["synth_id"] = id;
    }
  });
  document.addEventListener("htmx:beforeRequest", function (event) {
    if (event.detail.pathInfo && event.detail.pathInfo.requestPath === "/synthesis/start") {
      byId("synthesis-result").replaceChildren();
      running(true);
      poll();
    }
  });
  document.addEventListener("htmx:afterRequest", function (event) {
    if (event.detail.pathInfo && event.detail.pathInfo.requestPath === "/synthesis/start") {
      running(false);
      byId("synth-id").value = "";
    }
  });

  // a progress answer that arrives after the search's own answer is dropped (the search is over)
  document.addEventListener("htmx:beforeSwap", function (event) {
    if (event.detail.target && event.detail.target.id === "synthesis-progress" && polling === null) {
      event.detail.shouldSwap = false;
    }
  });

  // the spec from the form or from a pasted file: the pasted text starts as the form's spec
  document.addEventListener("change", function (event) {
    if (event.target.name !== "synth_mode") { return; }
    var panel = byId("synthesis"), spec = byId("synth-spec"), written = byId("synthesis-spec-text");
    panel.setAttribute("data-mode", event.target.value);
    if (event.target.value === "toml" && spec && !spec.value.trim() && written) { spec.value = written.textContent; }
  });

  function openCandidate(button) {
    var page = window.epicyclicPage;
    var rank = button.getAttribute("data-open-candidate");
    if (page && page.isDirty() && !window.confirm("The open file has edits that are not saved. They stay kept in "
        + "this browser and come back when you open it again. Open candidate " + rank + " as a new document?")) {
      return;
    }
    htmx.ajax("POST", "/synthesis/open", {
      target: "#workspace", swap: "innerHTML",
      values: { toml: button.getAttribute("data-toml"), name: button.getAttribute("data-name"),
                units: byId("units").value, lang: byId("lang").value }
    }).then(function () {
      var results = document.querySelector('[data-tab-button="results"]');
      if (results) { results.click(); }
    });
  }

  document.addEventListener("click", function (event) {
    var target = event.target;
    if (!target.closest) { return; }
    var open = target.closest("[data-open-candidate]");
    if (open) { openCandidate(open); return; }
    if (target.id === "synthesis-cancel" && byId("synth-id").value) {
      target.disabled = true;
      htmx.ajax("POST", "/synthesis/cancel", { target: "#synthesis-progress", swap: "none",
                                               values: { synth_id: byId("synth-id").value } });
      poll();
    }
  });
})();
