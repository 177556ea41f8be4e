// epicyclic serve: the little the page does in the browser (everything else is htmx and the server).
// Tabs; the page's state in its address (example or file, gear, operating point, tab, units) and the edits in
// the browser's storage; line numbers beside the editor and the error mark; Ctrl+Enter; clicking a gear;
// downloads; pictures at a readable size and enlarged.
"use strict";

(function () {
  function byId(id) { return document.getElementById(id); }
  function editor() { return byId("toml"); }
  function sourceName() { var s = document.querySelector("#ws input[name=source]"); return s ? s.value : ""; }
  function eol() { var e = document.querySelector("#ws input[name=eol]"); return e ? e.value : "lf"; }

  // ---- a request that a newer one replaced (hx-sync "replace": a gear clicked twice, a speed typed on) is
  // aborted on purpose; htmx reports that as an error (htmx:afterRequest, htmx:sendAbort), the page as what it is
  var consoleError = console.error;
  console.error = function (first) {
    if (typeof first === "string" && /^htmx:(afterRequest|sendAbort)\b/.test(first) && lastAbort > Date.now() - 1000) {
      console.info(first + " (replaced by a newer request)");
      return;
    }
    consoleError.apply(console, arguments);
  };
  var lastAbort = 0;
  document.addEventListener("htmx:abort", function () { lastAbort = Date.now(); }, true);
  document.addEventListener("htmx:beforeRequest", function () { lastAbort = Date.now(); }, true);

  // ---- this tab's id: the server caps the jobs per client (address and this id), so one tab cannot fill
  // the queue for the others
  var clientId = (window.crypto && crypto.randomUUID) ? crypto.randomUUID() : String(Math.random()).slice(2);
  document.addEventListener("htmx:configRequest", function (event) {
    event.detail.headers["X-Epicyclic-Client"] = clientId;
  });

  // ---- tabs: results, gears, pictures, geometry and rating, tools (the panels are in the results)
  var TABS = ["results", "gears", "pictures", "geometry", "tools", "synthesis"];
  function currentTab() { var ws = byId("ws"); return ws ? ws.getAttribute("data-tab") || "results" : "results"; }
  function showTab(tab, resize) {
    if (TABS.indexOf(tab) < 0) { tab = "results"; }
    var changed = byId("ws").getAttribute("data-tab") !== tab;
    byId("ws").setAttribute("data-tab", tab);
    document.querySelectorAll("[data-tab-button]").forEach(function (button) {
      var on = button.getAttribute("data-tab-button") === tab;
      button.setAttribute("aria-selected", on ? "true" : "false");
      button.classList.toggle("active", on);
    });
    if (tab === "pictures" && (changed || resize)) { sizePictures(); }  // each new picture is sized as it comes
    remember();
  }

  // ---- the page's state in its address: a reload or a shared link shows the same
  function operatingRows() {
    var rows = [];
    document.querySelectorAll("#opform tr[data-shaft]").forEach(function (tr) {
      function value(name) { var f = tr.querySelector("[name=" + name + "]"); return f ? f.value : ""; }
      rows.push([value("shaft"), value("role"), value("speed"), value("moment"), value("value")]);
    });
    return rows;
  }

  // the bundled example that is open (the server says so; a file of one's own named like an example is none)
  function openedExample() { var e = byId("opened-example"); return e ? e.value : ""; }

  function remember() {
    if (!editor()) { return; }
    var params = new URLSearchParams(), source = sourceName(), example = openedExample();
    if (example) { params.set("example", example); } else if (source) { params.set("file", source); }
    var gear = byId("gear");
    if (gear && gear.value) { params.set("gear", gear.value); }
    var rows = operatingRows();
    if (rows.length) { params.set("op", JSON.stringify(rows)); }
    if (currentTab() !== "results") { params.set("tab", currentTab()); }
    if (byId("units").value !== "file") { params.set("units", byId("units").value); }
    if (byId("lang").value !== "en") { params.set("lang", byId("lang").value); }
    var address = location.pathname + "?" + params.toString();
    // a new example, file or gear is a step of the history (Back returns to it); anything else replaces
    var key = (example ? "example:" + example : "file:" + source) + "|" + (gear ? gear.value : "");
    if (arriving !== null) {  // Back/Forward: the page shows the address's state once its answer has come
      if (key !== arriving) { return; }
      arriving = null;
      shownKey = key;  // arrived: this entry of the history is the page's now (replaced, not pushed)
    }
    if (shownKey !== null && key !== shownKey) {
      history.pushState(null, "", address);
    } else if (address !== location.pathname + location.search) {
      history.replaceState(null, "", address);
    }
    shownKey = key;
    showOpenFile(source, example);
  }
  var shownKey = null, arriving = null;

  function keyOf(params) {
    var example = params.get("example") || "", file = params.get("file") || "";
    return (example ? "example:" + example : "file:" + file) + "|" + (params.get("gear") || "");
  }

  // the operating point and gear of an address, as the fields the server reads when an example opens
  function restoreFields(params) {
    var restore = byId("restore"), rows = [];
    try { rows = JSON.parse(params.get("op") || "[]"); } catch (error) { rows = []; }
    restore.replaceChildren();
    function field(name, value) {
      var input = document.createElement("input");
      input.type = "hidden"; input.name = name; input.value = value;
      restore.appendChild(input);
    }
    (Array.isArray(rows) ? rows : []).forEach(function (row) {
      if (Array.isArray(row) && row.length === 5) {
        ["shaft", "role", "speed", "moment", "value"].forEach(function (name, k) { field(name, String(row[k])); });
      }
    });
    field("gear", params.get("gear") || "");
  }

  // Back and Forward: open the example or file of the address, or show its gear
  window.addEventListener("popstate", function () {
    var params = new URLSearchParams(location.search), key = keyOf(params);
    var example = params.get("example") || "", file = params.get("file") || "", gear = params.get("gear") || "";
    if (key === shownKey) { showTab(params.get("tab") || "results"); return; }
    arriving = key;
    showTab(params.get("tab") || "results");
    setTimeout(function () { if (arriving === key) { arriving = null; } }, 20000);  // no answer came: go on
    if (example && example !== openedExample() || !example && file && file !== sourceName()) {
      if (example) {
        restoreFields(params);
        byId("example").value = example;
        htmx.trigger(byId("reopen"), "epicyclic:open");
      } else if (!openKept(file)) {
        arriving = null;
        missingFile(file);
      }
    } else if (gear) {
      chooseGear(gear);
    } else {
      arriving = null;
    }
  });

  // a ?file= address whose file this browser does not keep (another browser, storage cleared): said so
  function missingFile(file, opening) {
    var note = byId("file-missing");
    if (!note) { return; }
    note.hidden = false;
    note.querySelector(".name").textContent = file;
    missingSince = opening ? openings : openings - 1;  // said until the reader opens another file
  }
  var openings = 0, missingSince = 0;

  // the example list shows the file that is open (an example, edited or not, or a file of one's own)
  function showOpenFile(source, example) {
    var select = byId("example"), mark = byId("example-file");
    if (!select || !mark) { return; }
    var edited = isDirty() ? " (edited)" : "";
    if (example) {
      mark.hidden = true;
      select.value = example;
      var option = select.options[select.selectedIndex];
      option.textContent = option.getAttribute("data-title") || option.textContent;
      if (!option.getAttribute("data-title")) { option.setAttribute("data-title", option.textContent); }
      option.textContent = option.getAttribute("data-title") + edited;
    } else {
      mark.hidden = false;
      mark.textContent = "file: " + source + edited;
      select.value = "";
      mark.selected = true;
    }
  }

  // ---- edits kept in the browser (localStorage), restored on reload; a warning before leaving with them
  var pristine = null;  // the text as it was opened (or last downloaded)
  function draftKey(source) { return "epicyclic:draft:" + source; }
  function isDirty() { return pristine !== null && editor() !== null && editor().value !== pristine; }
  function saveDraft() {
    if (!editor()) { return; }
    try {
      if (isDirty()) {
        localStorage.setItem(draftKey(sourceName()), JSON.stringify(
          { text: editor().value, eol: eol(), saved: new Date().toISOString() }));
        byId("draft-status").textContent = "edits kept in this browser";
      } else {
        localStorage.removeItem(draftKey(sourceName()));
        byId("draft-status").textContent = "";
      }
    } catch (error) { byId("draft-status").textContent = "edits cannot be kept (" + error.name + ")"; }
  }
  function readDraft(source) {
    try { return JSON.parse(localStorage.getItem(draftKey(source)) || "null"); } catch (error) { return null; }
  }
  var saving = null;
  function saveSoon() { clearTimeout(saving); saving = setTimeout(saveDraft, 250); }

  // for synthesis.js: a candidate opened in the editor asks first when the open file has unsaved edits
  window.epicyclicPage = { isDirty: function () { return isDirty(); } };

  window.addEventListener("beforeunload", function (event) {
    if (isDirty()) { saveDraft(); event.preventDefault(); event.returnValue = ""; }
  });

  // a newly opened workspace: remember its text; bring back edits kept for it
  function opened() {
    pristine = editor() ? editor().value : null;
    // the address's operating point and gear were for this opening only: the next example chosen from the list
    // (whose form holds #restore) opens with its own
    if (byId("restore")) { byId("restore").replaceChildren(); }
    openings += 1;
    if (byId("file-missing") && openings > missingSince + 1) { byId("file-missing").hidden = true; }
    if (pristine !== null && !openedExample()) {  // a file of one's own: kept to open it again on reload
      try {
        localStorage.setItem(draftKey("open:" + sourceName()), JSON.stringify(
          { text: pristine, eol: eol(), saved: new Date().toISOString() }));
      } catch (error) { /* storage full or off: a reload then opens the default example */ }
    }
    var draft = readDraft(sourceName());
    if (draft && typeof draft.text === "string" && draft.text !== pristine) {
      editor().value = draft.text;
      renderGutter();
      var note = byId("draft-restored");
      note.replaceChildren(document.createTextNode("your edits of " + String(draft.saved).replace("T", " ").slice(0, 19)
        + " UTC were restored "));
      var discard = document.createElement("button");
      discard.type = "button";
      discard.className = "link";
      discard.id = "discard-draft";
      discard.textContent = "discard them";
      note.appendChild(discard);
      byId("solve").click();
    }
  }

  // a file of one's own cannot be fetched again from the server: on reload its kept text is opened again
  function openKept(source) {
    var draft = readDraft(source) || readDraft("open:" + source);
    if (!draft) { return false; }
    var form = new FormData(), text = draft.eol === "crlf" ? draft.text.replace(/\n/g, "\r\n") : draft.text;
    form.append("file", new Blob([text], { type: "text/plain" }), source);
    form.append("units", byId("units").value);
    form.append("lang", byId("lang").value);
    fetch("/upload", { method: "POST", body: form, headers: { "X-Epicyclic-Client": clientId } })
      .then(function (response) { return response.text(); })
      .then(function (html) { htmx.swap("#workspace", html, { swapStyle: "innerHTML" }); });
    return true;
  }

  // ---- line numbers and the error line
  function errorLine() {
    var status = byId("editor-status");
    var line = status ? parseInt(status.getAttribute("data-line") || "", 10) : NaN;
    return isNaN(line) ? null : line;
  }

  function syncGutter() {
    var text = editor(), gutter = byId("gutter");
    if (!text || !gutter) { return; }
    // the textarea's horizontal scroll bar takes height from its text area, not from the gutter: the gutter
    // gets as much room below its last line, so that both scroll alike to the end (no drift by the bar)
    gutter.style.paddingBottom = "calc(.4rem + " + (text.offsetHeight - text.clientHeight) + "px)";
    gutter.scrollTop = text.scrollTop;
  }

  function renderGutter() {
    var text = editor(), gutter = byId("gutter");
    if (!text || !gutter) { return; }
    var count = text.value.split("\n").length, bad = errorLine(), parts = [];
    for (var k = 1; k <= count; k++) {
      parts.push(k === bad ? "<b class=\"err\">" + k + "</b>" : String(k));
    }
    gutter.innerHTML = parts.join("\n");  // numbers only: nothing the user wrote
    syncGutter();
  }

  function lineHeight(text) {
    var style = getComputedStyle(text), height = parseFloat(style.lineHeight);
    return isNaN(height) ? parseFloat(style.fontSize) * 1.45 : height;
  }

  // the view of the editor on line `line` (the middle of the text area), optionally selecting it
  function showLine(line, select) {
    var text = editor();
    if (!text || !line) { return; }
    var lines = text.value.split("\n"), start = 0;
    for (var k = 0; k < line - 1 && k < lines.length; k++) { start += lines[k].length + 1; }
    var end = start + (lines[line - 1] || "").length;
    if (select) { text.focus(); text.setSelectionRange(start, end); }
    text.scrollTop = Math.max(0, (line - 1) * lineHeight(text) - text.clientHeight / 2);
    syncGutter();
  }

  document.addEventListener("input", function (event) {
    if (event.target === editor()) { renderGutter(); saveSoon(); remember(); }
  });
  document.addEventListener("scroll", function (event) {
    if (event.target === editor()) { syncGutter(); }
  }, true);
  window.addEventListener("resize", function () { syncGutter(); sizePictures(); });

  // ---- while the results are being replaced (a gear change), the animation they hold stands still: it is
  // replaced with them, and in a browser that draws in software its frames take half a core
  document.addEventListener("htmx:beforeRequest", function (event) {
    if (event.detail.target && event.detail.target.id === "results") {
      document.querySelectorAll("#results .fig-body svg").forEach(function (svg) {
        if (svg.pauseAnimations) { svg.pauseAnimations(); }
      });
    }
  });
  document.addEventListener("htmx:afterRequest", function (event) {  // no new results: it turns again
    if (event.detail.target && event.detail.target.id === "results" && !event.detail.successful) {
      document.querySelectorAll("#results .fig-body svg").forEach(function (svg) {
        if (svg.unpauseAnimations) { svg.unpauseAnimations(); }
      });
    }
  });

  // ---- the worked solution stays open (or closed) as the reader left it while the results are replaced (a
  // language, unit or gear change)
  var explainOpen = false;
  document.addEventListener("toggle", function (event) {
    if (event.target.closest && event.target.closest("#explain")) { explainOpen = event.target.open; }
  }, true);
  function keepExplainOpen() {
    var details = document.querySelector("#explain > details");
    if (details && details.open !== explainOpen) { details.open = explainOpen; }
  }

  // ---- after every answer
  document.addEventListener("htmx:afterSettle", function (event) {
    var target = event.detail.target;
    keepExplainOpen();
    if (target && target.id === "workspace") { opened(); }
    renderGutter();
    if (target && (target.id === "workspace" || target.id === "results") && errorLine()) { showLine(errorLine(), false); }
    if (target && target.classList && target.classList.contains("fig-body")) { sizePicture(target); }
    showTab(currentTab());
    saveSoon();
  });
  document.addEventListener("DOMContentLoaded", function () {
    var params = new URLSearchParams(location.search);
    showTab(params.get("tab") || currentTab(), true);
    var file = params.get("file");
    if (!(file && !params.get("example") && openKept(file))) {
      if (file && !params.get("example")) { missingFile(file, true); }  // the server left its operating point out
      htmx.trigger(byId("initial-load"), "epicyclic:open");
    }
  });

  // ---- keys: Ctrl+Enter solves the text; Enter in a field never submits the form
  document.addEventListener("keydown", function (event) {
    if (event.target === editor() && event.key === "Enter" && (event.ctrlKey || event.metaKey)) {
      event.preventDefault();
      byId("solve").click();
    } else if (event.key === "Enter" && event.target.tagName === "INPUT") {
      event.preventDefault();
      event.target.dispatchEvent(new Event("change", { bubbles: true }));
    } else if (event.key === "Enter" && event.target.hasAttribute && event.target.hasAttribute("data-gear")) {
      chooseGear(event.target.getAttribute("data-gear"));
    }
  });
  document.addEventListener("submit", function (event) {
    if (event.target.method !== "dialog") { event.preventDefault(); }  // a dialog's form only closes it
  });

  // ---- clicks: a gear row solves in that gear; "line N" jumps there; downloads
  function chooseGear(gear) {
    var select = byId("gear");
    if (!select || select.value === gear) { return; }
    select.value = gear;
    select.dispatchEvent(new Event("change", { bubbles: true }));
  }

  function fileName(response, fallback) {
    var header = response.headers.get("Content-Disposition") || "";
    var match = /filename="([^"]+)"/.exec(header);
    return match ? match[1] : fallback;
  }

  // a download is a POST of the page's form to `path` (/download/json, /save/speed, ...); the answer is
  // saved under the server's file name, or, when the input is bad, its message is shown above the results
  function download(path) {
    var status = byId("download-status");
    var what = path.split("/").pop();
    status.textContent = "preparing " + what + "…";
    fetch(path, { method: "POST", body: new FormData(byId("ws")), headers: { "X-Epicyclic-Client": clientId } })
      .then(function (response) {
        if (!response.ok) {
          return response.text().then(function (html) {
            htmx.swap("#results", html, { swapStyle: "afterbegin" });
            status.textContent = what + ": not possible, see the message";
          });
        }
        return response.blob().then(function (blob) {
          var link = document.createElement("a");
          link.href = URL.createObjectURL(blob);
          link.download = fileName(response, "epicyclic-" + what);
          document.body.appendChild(link);
          link.click();
          link.remove();
          setTimeout(function () { URL.revokeObjectURL(link.href); }, 10000);
          status.textContent = "downloaded " + link.download;
          if (what === "toml") { pristine = editor().value; saveDraft(); remember(); }  // saved: nothing to lose
        });
      })
      .catch(function (error) { status.textContent = what + ": " + error; });
  }

  // ---- pictures at a readable size: the smallest text of a picture at least 11 px on the screen where the
  // panel has room for it, and never wider than the panel (a wide picture, the lever diagram of a transmission
  // or its power flow, is shown whole, its text smaller; enlarge shows it at the window's width)
  var SMALLEST_TEXT = 11;
  function smallestFont(svg) {
    var smallest = Infinity;
    svg.querySelectorAll("text").forEach(function (text) {
      var match = /font(?:-size)?:\s*(?:[a-z]+\s+)*([\d.]+)px/.exec(text.getAttribute("style") || "");
      var size = match ? parseFloat(match[1]) : parseFloat(text.getAttribute("font-size") || "");
      if (size > 0 && size < smallest) { smallest = size; }
    });
    return smallest;
  }
  function sizePicture(body) {
    var svg = body.querySelector("svg");
    if (!svg || body.offsetWidth === 0 || svg.querySelector("animateTransform")) { return; }
    var box = svg.viewBox && svg.viewBox.baseVal;
    if (!box || !box.width) { return; }
    var font = smallestFont(svg), room = body.clientWidth;
    var needed = isFinite(font) ? box.width * SMALLEST_TEXT / font : room;
    // as wide as the panel (no wider than 1.6 times its own size), wider where its smallest text needs it, but
    // within the panel: nothing of it is cut off at the panel's edge
    svg.style.width = Math.min(Math.max(Math.min(room, box.width * 1.6), needed), room) + "px";
    svg.style.maxWidth = "none";
    svg.style.height = "auto";
  }
  function sizePictures() { document.querySelectorAll(".fig-body").forEach(sizePicture); }

  // ---- a picture at the full width of the window (a copy of its SVG in a dialog)
  function enlarge(figureId) {
    var dialog = byId("zoom"), svg = document.querySelector("#" + figureId + " .fig-body svg");
    if (dialog && window.epicyclicCharts && epicyclicCharts.enlarge(byId(figureId), dialog.querySelector(".zoom-body"))) {
      dialog.showModal();  // a chart the browser draws (charts.js): drawn again at the window's width
      return;
    }
    if (!dialog || !svg) { return; }
    var copy = svg.cloneNode(true);
    copy.style.width = "";
    copy.style.maxWidth = "";
    dialog.querySelector(".zoom-body").replaceChildren(copy);
    dialog.showModal();
  }

  document.addEventListener("change", function (event) {
    if (event.target.closest && event.target.closest("#opform")) { setTimeout(remember, 0); }
  });

  document.addEventListener("click", function (event) {
    var target = event.target;
    if (!target.closest) { return; }
    var tab = target.closest("[data-tab-button]");
    if (tab) { showTab(tab.getAttribute("data-tab-button"), true); return; }
    var row = target.closest("[data-gear]");
    if (row) { chooseGear(row.getAttribute("data-gear")); return; }
    var link = target.closest("a.goto");
    if (link) { event.preventDefault(); showLine(parseInt(link.getAttribute("data-line"), 10), true); return; }
    if (target.id === "discard-draft") {
      localStorage.removeItem(draftKey(sourceName()));
      editor().value = pristine;
      byId("draft-restored").textContent = "edits discarded";
      renderGutter();
      byId("solve").click();
      return;
    }
    var button = target.closest("[data-download]");
    if (button) { download(button.getAttribute("data-download")); return; }
    var zoom = target.closest("[data-enlarge]");
    if (zoom) { enlarge(zoom.getAttribute("data-enlarge")); return; }
    if (target.id === "zoom") { target.close(); }  // a click beside the picture closes it
  });
})();
