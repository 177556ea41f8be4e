// epicyclic serve: the little the page does in the browser (everything else is htmx and the server).
// Line numbers beside the editor and the error mark, Ctrl+Enter, clicking a gear, downloads, enlarged pictures.
"use strict";

(function () {
  function editor() { return document.getElementById("toml"); }

  // ---- this tab's id: the server caps the jobs per client (address and this id), so one tab cannot fill
  // the queue for the others
  var clientId = (window.crypto && crypto.randomUUID) ? crypto.randomUUID() : String(Math.random()).slice(2);
  document.addEventListener("htmx:configRequest", function (event) {
    event.detail.headers["X-Epicyclic-Client"] = clientId;
  });

  // ---- line numbers and the error line
  function errorLine() {
    var status = document.getElementById("editor-status");
    var line = status ? parseInt(status.getAttribute("data-line") || "", 10) : NaN;
    return isNaN(line) ? null : line;
  }

  function renderGutter() {
    var text = editor(), gutter = document.getElementById("gutter");
    if (!text || !gutter) { return; }
    var count = text.value.split("\n").length, bad = errorLine(), parts = [];
    for (var k = 1; k <= count; k++) {
      parts.push(k === bad ? "<b class=\"err\">" + k + "</b>" : String(k));
    }
    gutter.innerHTML = parts.join("\n");  // numbers only: nothing the user wrote
    gutter.scrollTop = text.scrollTop;
  }

  function goToLine(line) {
    var text = editor();
    if (!text) { return; }
    var lines = text.value.split("\n"), start = 0;
    for (var k = 0; k < line - 1 && k < lines.length; k++) { start += lines[k].length + 1; }
    var end = start + (lines[line - 1] || "").length;
    text.focus();
    text.setSelectionRange(start, end);
    var height = text.scrollHeight / Math.max(lines.length, 1);
    text.scrollTop = Math.max(0, (line - 5) * height);
  }

  document.addEventListener("input", function (event) {
    if (event.target === editor()) { renderGutter(); }
  });
  document.addEventListener("scroll", function (event) {
    if (event.target === editor()) { document.getElementById("gutter").scrollTop = editor().scrollTop; }
  }, true);
  document.addEventListener("htmx:afterSettle", renderGutter);
  document.addEventListener("DOMContentLoaded", renderGutter);

  // ---- keys: Ctrl+Enter solves the text; Enter in a field never submits the form
  document.addEventListener("keydown", function (event) {
    if (event.target === editor() && event.key === "Enter" && (event.ctrlKey || event.metaKey)) {
      event.preventDefault();
      document.getElementById("solve").click();
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
    var select = document.getElementById("gear");
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
    var status = document.getElementById("download-status");
    var what = path.split("/").pop();
    status.textContent = "preparing " + what + "…";
    fetch(path, { method: "POST", body: new FormData(document.getElementById("ws")),
                  headers: { "X-Epicyclic-Client": clientId } })
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
        });
      })
      .catch(function (error) { status.textContent = what + ": " + error; });
  }

  // ---- a picture at the full width of the window (a copy of its SVG in a dialog)
  function enlarge(figureId) {
    var dialog = document.getElementById("zoom"), svg = document.querySelector("#" + figureId + " .fig-body svg");
    if (!dialog || !svg) { return; }
    var body = dialog.querySelector(".zoom-body");
    body.replaceChildren(svg.cloneNode(true));
    dialog.showModal();
  }

  document.addEventListener("click", function (event) {
    var target = event.target;
    var row = target.closest ? target.closest("[data-gear]") : null;
    if (row) { chooseGear(row.getAttribute("data-gear")); return; }
    var link = target.closest ? target.closest("a.goto") : null;
    if (link) { event.preventDefault(); goToLine(parseInt(link.getAttribute("data-line"), 10)); return; }
    var button = target.closest ? target.closest("[data-download]") : null;
    if (button) { download(button.getAttribute("data-download")); return; }
    var zoom = target.closest ? target.closest("[data-enlarge]") : null;
    if (zoom) { enlarge(zoom.getAttribute("data-enlarge")); return; }
    if (target.id === "zoom") { target.close(); }  // a click beside the picture closes it
  });
})();
