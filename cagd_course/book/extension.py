"""The course's Sphinx extension: a "run it yourself" box on every notebook page, and what keeps the book local.

`cagd_pages` (set by the build) maps each docname of a chapter or exercise
notebook to what its box says: the notebook's path in the course folder, the
page it pairs with, and the error of a chapter that failed to execute.
"""

from __future__ import annotations

from docutils import nodes
from sphinx.addnodes import pending_xref

__all__ = ["setup"]


def _literal(text: str) -> nodes.literal:
    return nodes.literal(text=text)


def _page_link(source: str, target: str, title: str) -> pending_xref:
    """A link to another page of the book, resolved by Sphinx (it knows each builder's file names)."""
    return pending_xref(
        "",
        nodes.inline(text=title),
        refdomain="std",
        reftype="doc",
        reftarget="/" + target,
        refexplicit=True,
        refdoc=source,
        refwarn=True,
    )


def _run_box(docname: str, page: dict) -> nodes.admonition:
    box = nodes.admonition(classes=["tip", "cagd-run-box"])
    box += nodes.title(text="Run it yourself")
    notebook = page["notebook"]
    if page["kind"] == "chapter":
        text = nodes.paragraph()
        text += nodes.Text("This page is the notebook ")
        text += _literal(notebook)
        text += nodes.Text(" (the download button at the top gives it without outputs). In the course folder, ")
        text += _literal("./course lab")
        text += nodes.Text(" opens it in JupyterLab, where every control of every explorer is live.")
        box += text
        if page.get("partner"):
            more = nodes.paragraph()
            more += nodes.Text("Then write the algorithms yourself: ")
            more += _page_link(docname, page["partner"], page["partner_title"])
            more += nodes.Text(".")
            box += more
    else:
        text = nodes.paragraph()
        text += nodes.Text("Open ")
        text += _literal(notebook)
        text += nodes.Text(" with ")
        text += _literal("./course lab")
        text += nodes.Text(", write each function in place of its stub and run its self-check cell; ")
        text += _literal(f"./course cagd check {notebook}")
        text += nodes.Text(" grades the whole notebook from a terminal.")
        box += text
        if page.get("partner"):
            more = nodes.paragraph()
            more += nodes.Text("The chapter: ")
            more += _page_link(docname, page["partner"], page["partner_title"])
            more += nodes.Text(".")
            box += more
    return box


def _failure_box(page: dict) -> nodes.error:
    box = nodes.error()
    box += nodes.paragraph(text=f"This chapter failed to execute, so its outputs are missing: {page['failure']}")
    return box


def add_run_box(app, doctree: nodes.document) -> None:
    """Put the box right under the page title of every chapter and exercise notebook."""
    page = app.config.cagd_pages.get(app.env.docname)
    if page is None:
        return
    section = next(iter(doctree.findall(nodes.section)), None)
    if section is None:
        return
    position = section.index(section.next_node(nodes.title)) + 1
    boxes = [_run_box(app.env.docname, page)]
    if page.get("failure"):
        boxes.insert(0, _failure_box(page))
    for offset, box in enumerate(boxes):
        section.insert(position + offset, box)


def use_work_folder(app) -> None:
    """Write MyST-NB's executed notebooks and output files into the build's work folder.

    MyST-NB puts them beside the HTML folder by default, which for `--out DIR`
    would be a folder of the user's next to DIR.
    """
    folder = app.config.cagd_output_folder
    if folder and hasattr(app.env, "mystnb_config"):
        app.env.mystnb_config = app.env.mystnb_config.copy(output_folder=folder)


def drop_widget_state(app, env) -> None:
    """Leave the saved widget state out of the pages: without a widget manager it is dead weight (megabytes)."""
    for data in getattr(env, "nb_metadata", {}).values():
        data.get("js_files", {}).pop("ipywidgets_state", None)


def keep_tagged_formulas_whole(app, doctree: nodes.document) -> None:
    """Hand a displayed formula with a `\\tag` to MathJax as written.

    Sphinx wraps every displayed formula that holds a line break in `\\begin{split}`, and MathJax refuses
    `\\tag` there ("\\tag not allowed in split environment"): a numbered formula with a matrix, cases or an
    aligned block would show as an error box. Its own environments already lay out its lines.
    """
    opening, closing = app.config.mathjax_display
    for node in doctree.findall(nodes.math_block):
        text = node.astext()
        if "\\tag" in text and not node.get("number") and not node.get("nowrap"):
            node["nowrap"] = True  # written out as it is: the delimiters go in with it
            node.children = [nodes.Text(f"{opening}{text}{closing}")]


def setup(app):
    app.add_config_value("cagd_pages", {}, "env", dict)
    # A digest of the course's code: when it changes, every page is read again (its outputs may change).
    app.add_config_value("cagd_fingerprint", "", "env", str)
    app.add_config_value("cagd_output_folder", "", "env", str)
    # After MyST-NB's own builder-inited handler (priority 500) has made its configuration.
    app.connect("builder-inited", use_work_folder, priority=900)
    app.connect("doctree-read", add_run_box)
    app.connect("doctree-read", keep_tagged_formulas_whole)
    app.connect("env-updated", drop_widget_state)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
