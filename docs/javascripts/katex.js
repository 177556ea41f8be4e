// KaTeX for the formulas of the site (pymdownx.arithmatex, generic mode writes \( \) and \[ \]).
// The renderer is vendored under docs/vendor/katex: the site loads nothing from a CDN.
document$.subscribe(({ body }) => {
  renderMathInElement(body, {
    delimiters: [
      { left: "\\[", right: "\\]", display: true },
      { left: "\\(", right: "\\)", display: false },
    ],
    throwOnError: false,
  });
});
