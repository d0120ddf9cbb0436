"""Sphinx configuration of the mechverify API reference (``make docs``; warnings are errors)."""

project = "mechverify"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon"]
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
autodoc_typehints = "description"
autodoc_member_order = "bysource"
napoleon_google_docstring = True
napoleon_numpy_docstring = True
nitpicky = False
suppress_warnings = ["ref.python"]  # an unresolved cross-reference is not a build error (duplicate names in fea)
html_theme = "alabaster"
exclude_patterns = ["_build"]
