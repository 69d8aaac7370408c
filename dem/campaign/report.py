"""The campaign report: one self-contained HTML file, the tables as CSV, everything in one HDF5.

Each campaign step returns outputs with (optionally) these keys:

* ``tables``: list of ``{"name", "title", "csv"}`` — CSV files (relative to the campaign folder);
* ``figures``: list of ``{"path", "caption"}`` — PNG files (relative), embedded as data URIs;
* ``findings``: list of sentences computed from the results (never written by hand);
* ``summary``: a short paragraph describing what the step did.
"""
from __future__ import annotations

import base64
import csv
import html
import json
from pathlib import Path

import h5py
import numpy as np

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


def _read_csv(path: Path) -> list[dict]:
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def _fmt(v: str) -> str:
    try:
        x = float(v)
    except (TypeError, ValueError):
        return html.escape(str(v))
    if x != x:
        return "–"
    if x == int(x) and abs(x) < 1e6 and "." not in str(v) and "e" not in str(v).lower():
        return str(int(x))
    return f"{x:.4g}"


def _table_html(rows: list[dict], title: str, name: str) -> str:
    if not rows:
        return f"<p>(table {html.escape(title)} is empty)</p>"
    cols = list(rows[0])
    head = "".join(f"<th>{html.escape(c)}</th>" for c in cols)
    body = "".join("<tr>" + "".join(f"<td>{_fmt(r[c])}</td>" for c in cols) + "</tr>" for r in rows)
    return (f'<div class="wrap"><table class="data" data-name="{html.escape(name)}"><caption>{html.escape(title)}</caption>'
            f"<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table></div>")


def _params_html(params: dict, prov: dict) -> str:
    """The campaign's parameters and versions as a two-column table (nested values as compact JSON)."""
    def val(v) -> str:
        return html.escape(v if isinstance(v, str) else json.dumps(v, separators=(", ", ": ")))

    rows = "".join(f"<tr><td>{html.escape(str(k))}</td><td>{val(v)}</td></tr>" for k, v in params.items())
    rows += "".join(f"<tr><td>version: {html.escape(str(k))}</td><td>{val(v)}</td></tr>" for k, v in prov.items())
    return f"<div class='wrap'><table class='params'><tr><th>parameter</th><th>value</th></tr>{rows}</table></div>"


def _num(v) -> float:
    try:
        return float(v)
    except (TypeError, ValueError):
        return float("nan")


def _summary_html(tables: dict[str, list[dict]]) -> str:
    """Per specimen: lambda of the laboratory, the limit analysis and the DEM, the least shake threshold;
    and the monument's assessment verdicts; from the steps' tables (what was not run is left blank)."""
    ids: list[str] = []
    for name in ("lab", "analytic", "shake"):
        ids += [r["id"] for r in tables.get(name, []) if r.get("id") and r["id"] not in ids]
    out = []
    if ids:
        def first(name, sid, col):
            r = next((r for r in tables.get(name, []) if r.get("id") == sid), None)
            return "" if r is None else _fmt(r.get(col, ""))

        rows = []
        for sid in ids:
            lam_la = next((first("analytic", sid, c) for c in ("lambda_discrete_free", "lambda_discrete_glued")
                           if first("analytic", sid, c)), "") or first("lab", sid, "lambda_lp_effective")
            shakes = [r for r in tables.get("shake", []) if r.get("id") == sid and _num(r.get("a_dem_g")) == _num(r.get("a_dem_g"))]
            low = min(shakes, key=lambda r: _num(r["a_dem_g"])) if shakes else None
            rows.append(f"<tr><td>{html.escape(sid)}</td><td>{first('lab', sid, 'lambda_lab_mean')}</td><td>{lam_la}</td>"
                        f"<td>{first('lab', sid, 'lambda_dem_effective_mean')}</td>"
                        f"<td>{'' if low is None else _fmt(low['a_dem_g']) + ' g at ' + _fmt(low['freq_Hz']) + ' Hz'}</td></tr>")
        out.append("<div class='wrap'><table class='data'><caption>Per specimen</caption><tr><th>specimen</th>"
                   "<th>lambda laboratory</th><th>lambda limit analysis</th><th>lambda DEM</th>"
                   "<th>least shake threshold (DEM)</th></tr>" + "".join(rows) + "</table></div>")
    if tables.get("assess"):
        rows = "".join(
            f"<tr><td>{html.escape(r['configuration'])}</td><td>{'yes' if r['frp'] == 'True' else 'no'}</td>"
            f"<td>{_fmt(r['lambda'])}</td><td>{_fmt(r.get('a0_over_pga_published_convention', ''))}</td>"
            f"<td>{_fmt(r['safety_index_linear'])}</td><td>{_fmt(r['safety_index_displacement'])}</td>"
            f"<td>{'verified' if r['verified'] == 'True' else 'NOT verified'}</td></tr>" for r in tables["assess"])
        out.append("<div class='wrap'><table class='data'><caption>Noh Gumbad: code checks (SLV) and the published "
                   "convention</caption><tr><th>configuration</th><th>FRP</th><th>lambda</th><th>a0*/PGA</th>"
                   "<th>SI linear</th><th>SI displacement</th><th>verdict</th></tr>" + rows + "</table></div>")
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
    tables: dict[str, list[dict]] = {}
    for rec in manifest.get("steps", {}).values():
        for t in rec["outputs"].get("tables", []):
            tables[t["name"]] = _read_csv(out / t["csv"])
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
            parts.append(_table_html(rows, t["title"], t["name"]))
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
    _write_h5(h5, manifest, tables)
    return {"report": str(report), "hdf5": str(h5), "n_figures": n_fig, "n_tables": n_tab}


def _write_h5(path: Path, manifest: dict, tables: dict[str, list[dict]]) -> None:
    with atomic_path(path, overwrite=True) as tmp:
        with h5py.File(tmp, "w") as f:
            f.attrs["parameters"] = json.dumps(manifest.get("parameters", {}))
            f.attrs["provenance"] = json.dumps(manifest.get("provenance", {}))
            f.attrs["manifest"] = to_json(manifest)
            g = f.create_group("tables")
            for name, rows in tables.items():
                tg = g.create_group(name)
                for col in (rows[0] if rows else {}):
                    vals = [r[col] for r in rows]
                    try:
                        tg.create_dataset(col, data=np.array([float(v) if v != "" else np.nan for v in vals]))
                    except ValueError:
                        tg.create_dataset(col, data=np.array(vals, dtype=h5py.string_dtype()))
