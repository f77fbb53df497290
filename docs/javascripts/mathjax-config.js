// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// MathJax 2 configuration, read by MathJax.js (loaded after this file):
// typeset only what pymdownx.arithmatex marked, \( \) inline and \[ \]
// displayed, with the SVG output, which needs no web fonts; MathJax itself
// is put into the site by etc/docs/mathjaxHook.py.
window.MathJax = {
    jax: ["input/TeX", "output/SVG"],
    extensions: ["tex2jax.js"],
    TeX: {extensions: ["AMSmath.js", "AMSsymbols.js", "noErrors.js", "noUndefined.js"]},
    tex2jax: {
        inlineMath: [["\\(", "\\)"]],
        displayMath: [["\\[", "\\]"]],
        processEscapes: false,
        processEnvironments: false,
        ignoreClass: ".*|",
        processClass: "arithmatex"
    },
    SVG: {font: "TeX", linebreaks: {automatic: false}},
    messageStyle: "none",
    showMathMenu: false
};
