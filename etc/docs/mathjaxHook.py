# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""MkDocs hook (mkdocs.yml `hooks`): puts MathJax into the built site, so
that the pages' equations render without a network.

The pages' math is marked up by pymdownx.arithmatex (generic mode) and
typeset in the browser by MathJax 2 from Debian's libjs-mathjax, configured
by docs/javascripts/mathjax-config.js. After the build this hook copies the
part of MathJax that this configuration loads (the TeX input, the SVG
output with the TeX font, the extensions) to javascripts/mathjax/ in the
site; the whole package with its other fonts is ten times larger.
"""

import os
import shutil

from mkdocs.exceptions import PluginError

MATHJAX = "/usr/share/javascript/mathjax"
TARGET = os.path.join("javascripts", "mathjax")
# What the configuration loads, relative to MathJax's root
PARTS = [
    "MathJax.js",
    "extensions",
    "localization/en",
    "jax/element",
    "jax/input/TeX",
    "jax/output/SVG/config.js",
    "jax/output/SVG/jax.js",
    "jax/output/SVG/autoload",
    "jax/output/SVG/fonts/TeX",
]


def on_post_build(config, **kwargs):
    if not os.path.isfile(os.path.join(MATHJAX, "MathJax.js")):
        raise PluginError(
            "MathJax not found in %s: install Debian's libjs-mathjax "
            "(etc/install)" % MATHJAX)
    target = os.path.join(config["site_dir"], TARGET)
    for part in PARTS:
        source = os.path.join(MATHJAX, part)
        destination = os.path.join(target, part)
        os.makedirs(os.path.dirname(destination), exist_ok=True)
        if os.path.isdir(source):
            shutil.copytree(source, destination, dirs_exist_ok=True)
        elif os.path.isfile(source):
            shutil.copy2(source, destination)
        else:
            raise PluginError("MathJax in %s lacks %s" % (MATHJAX, part))
