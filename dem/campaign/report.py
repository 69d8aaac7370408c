"""The campaign report: one self-contained HTML file, the tables as CSV, everything in one HDF5.

Each campaign step returns outputs with (optionally) these keys:

* ``tables``: list of ``{"name", "title", "csv"}`` — CSV files (relative to the campaign folder), each with
  its schema beside it, through which the report and ``campaign.h5`` read it typed (:mod:`dem.common.tables`);
* ``figures``: list of ``{"path", "caption"}`` — PNG files (relative), embedded as data URIs;
* ``findings``: list of sentences computed from the results (never written by hand);
* ``summary``: a short paragraph describing what the step did.

The sections are titled by the steps' declared descriptions and the summary is built from the experiments'
declared parts (:mod:`dem.experiments.registry`).
"""
from __future__ import annotations

import base64
import html
import json
from pathlib import Path

import h5py

from dem.common.tables import Schema, cells_html, read_csv, table_html, write_h5_group
from dem.experiments.registry import summaries
from foundation.io import atomic_path, to_json

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}
h1{border-bottom:2px solid #8a6d3b}h2{margin-top:2em;border-bottom:1px solid #ccc}
table{border-collapse:collapse;font-size:13px;margin:0.8em 0}th,td{border:1px solid #bbb;padding:3px 7px;text-align:right}
th{background:#f3efe6}td:first-child,th:first-child{text-align:left}
figure{display:inline-block;margin:0.5em;vertical-align:top;max-width:100%}figure img{max-width:540px;width:100%;border:1px solid #ddd}
figcaption{font-size:12px;color:#555;max-width:520px}.findings li{margin:0.3em 0}.meta{font-size:12px;color:#555;overflow-wrap:anywhere}
.wrap{max-width:100%;overflow-x:auto}table.data,table.params{font-size:12px}th{overflow-wrap:anywhere}
table.data[data-name$=calculation] td{text-align:left}table.params td{text-align:left;overflow-wrap:anywhere}
"""


def _params_html(params: dict, prov: dict) -> str:
    """The campaign's parameters and versions as a two-column table (nested values as compact JSON)."""
    def val(v) -> str:
        return html.escape(v if isinstance(v, str) else json.dumps(v, separators=(", ", ": ")))

    rows = "".join(f"<tr><td>{html.escape(str(k))}</td><td>{val(v)}</td></tr>" for k, v in params.items())
    rows += "".join(f"<tr><td>version: {html.escape(str(k))}</td><td>{val(v)}</td></tr>" for k, v in prov.items())
    return f"<div class='wrap'><table class='params'><tr><th>parameter</th><th>value</th></tr>{rows}</table></div>"


def _summary_html(tables: dict[str, list[dict]]) -> str:
    """The experiments' parts of the summary (their declarations, :mod:`dem.experiments.registry`), from the
    steps' typed tables: per specimen their columns side by side (what was not run is left blank), then
    any table of their own."""
    parts = summaries()
    per_specimen = [p for p in parts if p.columns]
    ids: list[str] = []
    for p in per_specimen:
        for name in p.ids:
            ids += [r["id"] for r in tables.get(name, []) if r.get("id") and r["id"] not in ids]
    out = []
    if ids:
        headers = ["specimen"] + [c for p in per_specimen for c in p.columns]
        rows = [[html.escape(sid)] + [c for p in per_specimen for c in p.cells(tables, sid)] for sid in ids]
        out.append(cells_html("Per specimen", headers, rows))
    for p in parts:
        own = p.table(tables) if p.table is not None else None
        if own is not None:
            out.append(cells_html(*own))
    return "".join(out) if out else "<p>No step with per-specimen results was run.</p>"


def _figure_html(path: Path, caption: str) -> str:
    data = base64.b64encode(path.read_bytes()).decode("ascii")
    return (f'<figure><img alt="{html.escape(caption)}" src="data:image/png;base64,{data}">'
            f"<figcaption>{html.escape(caption)}</figcaption></figure>")


def build_report(out: Path, manifest: dict, step_titles: dict[str, str]) -> dict:
    """Write ``report.html`` and ``campaign.h5`` into ``out``; return their paths and counts."""
    parts = [f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>archdem campaign</title><style>{_CSS}</style></head><body>",
             "<h1>archdem — virtual test campaign</h1>"]
    params = manifest.get("parameters", {})
    prov = manifest.get("provenance", {})
    tables: dict[str, list[dict]] = {}  # typed rows, read with the schema written beside each table
    schemas: dict[str, Schema] = {}
    for rec in manifest.get("steps", {}).values():
        for t in rec["outputs"].get("tables", []):
            schemas[t["name"]], tables[t["name"]] = read_csv(out / t["csv"])
    parts.append("<h2>Summary</h2>" + _summary_html(tables))
    findings_all: list[str] = []
    for name, rec in manifest.get("steps", {}).items():
        findings_all += [f"[{name}] {f}" for f in rec["outputs"].get("findings", [])]
    parts.append("<h2>Findings</h2>")
    if findings_all:
        parts.append("<ul class='findings'>" + "".join(f"<li>{html.escape(f)}</li>" for f in findings_all) + "</ul>")
    else:
        parts.append("<p>No step produced findings yet.</p>")
    parts.append("<h2>Parameters</h2>" + _params_html(params, prov))
    n_fig = n_tab = 0
    for name, rec in manifest.get("steps", {}).items():
        o = rec["outputs"]
        parts.append(f"<h2 id='{html.escape(name)}'>{html.escape(step_titles.get(name, name))}</h2>")
        parts.append(f"<p class='meta'>step <code>{html.escape(name)}</code>, {rec.get('wall_s', 0):.1f} s</p>")
        if o.get("summary"):
            parts.append(f"<p>{html.escape(o['summary'])}</p>")
        for t in o.get("tables", []):
            rows = tables[t["name"]]
            parts.append(table_html(rows, schemas[t["name"]], t["title"], t["name"]))
            parts.append(f"<p class='meta'>CSV: <code>{html.escape(t['csv'])}</code></p>")
            n_tab += 1
        for f in o.get("figures", []):
            parts.append(_figure_html(out / f["path"], f["caption"]))
            n_fig += 1
    parts.append("</body></html>")
    report = out / "report.html"
    with atomic_path(report, overwrite=True) as tmp:
        tmp.write_text("\n".join(parts), encoding="utf-8")
    h5 = out / "campaign.h5"
    _write_h5(h5, manifest, tables, schemas)
    return {"report": str(report), "hdf5": str(h5), "n_figures": n_fig, "n_tables": n_tab}


def _write_h5(path: Path, manifest: dict, tables: dict[str, list[dict]], schemas: dict[str, Schema]) -> None:
    with atomic_path(path, overwrite=True) as tmp:
        with h5py.File(tmp, "w") as f:
            f.attrs["parameters"] = json.dumps(manifest.get("parameters", {}))
            f.attrs["provenance"] = json.dumps(manifest.get("provenance", {}))
            f.attrs["manifest"] = to_json(manifest)
            g = f.create_group("tables")
            for name, rows in tables.items():
                write_h5_group(g.create_group(name), rows, schemas[name])
