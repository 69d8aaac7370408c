"""Figures and the one-page HTML report of a code-based assessment. Plotting only; no physics here."""
from __future__ import annotations

import base64
import html
import io
import json
import math

import numpy as np
from matplotlib.figure import Figure

from analytic.motions.spectra import rebuild
from specimens.constants import G
from specimens.io import atomic_path

_CSS = ("body{font-family:system-ui,sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;color:#222}"
        "h1{border-bottom:2px solid #8a6d3b}table{border-collapse:collapse;font-size:13px;margin:0.8em 0}"
        "th,td{border:1px solid #bbb;padding:3px 7px;text-align:right}th{background:#f3efe6}"
        "td:first-child,th:first-child{text-align:left}img{max-width:480px;border:1px solid #ddd;margin:0.3em}"
        ".no{color:#a00;font-weight:bold}.yes{color:#070;font-weight:bold}.meta{font-size:12px;color:#555}")


def hinges_text(hinges: list[dict]) -> str:
    """Hinges as "polar angle (joint face)", left to right."""
    return ", ".join(f"{h['angle_rad']:.3f} rad ({(h['joint'] + ' ') if 'joint' in h else ''}{h['face']})" for h in hinges)


def spectra_figure(site, damping: float):
    """Acceleration and displacement spectra of the site at 5 % and at the mechanism's ``damping`` [%]."""

    T = np.linspace(0.0, site.t_max, 400)
    fig = Figure(figsize=(7, 3.2))
    ax = fig.subplots(1, 2)
    for s, style, lab in ((site, "k-", f"{site.describe().get('damping', 5):g} %"),
                          (rebuild(site, damping=damping), "C3--", f"{damping:g} % (mechanism)")):
        ax[0].plot(T, s.Se(T) / G, style, label=lab)
        ax[1].plot(T, s.SDe(T) * 1e3, style, label=lab)
    ax[0].set(xlabel="T [s]", ylabel="Se [g]", title="acceleration")
    ax[1].set(xlabel="T [s]", ylabel="SDe [mm]", title="displacement")
    ax[0].legend(fontsize=8)
    fig.tight_layout()
    return fig


def capacity_figure(res, site, frp=None):
    """Capacity curves a*(d*) (and the codes' linear one) against the demand spectrum at the
    mechanism's damping in acceleration-displacement form, with the ultimate displacement and the
    period line of the displacement check."""

    fig = Figure(figsize=(6, 4))
    ax = fig.subplots()
    for r, col, lab in ((res, "k", "unreinforced"), (frp, "C0", "with FRP")):
        if r is None:
            continue
        c = r.curve
        ax.plot(c.d_star * 1e3, c.a_star / G, color=col, lw=2, label=f"capacity, {lab}")
        ax.plot([0, c.d0_star * 1e3], [c.a0_star / G, 0], color=col, lw=0.8, ls=":")
        chk = next(x for x in r.checks if x["kind"] == "non-linear")
        ax.plot([chk["d_u_star"] * 1e3], [chk["a_u_star"] / G], "o", color=col)
        ax.annotate(f"{chk['limit_state']} d_u*", (chk["d_u_star"] * 1e3, chk["a_u_star"] / G), fontsize=8,
                    xytext=(4, 4), textcoords="offset points")
    chk = next(x for x in res.checks if x["kind"] == "non-linear")
    dem = rebuild(site, damping=chk["damping"])
    T = np.linspace(1e-3, dem.t_max, 600)
    ax.plot(dem.SDe(T) * 1e3, dem.Se(T) / G, "C3--", label=f"site demand, {chk['damping']:g} % damping")
    dmax = max(res.curve.d0_star, frp.curve.d0_star if frp is not None else 0) * 1e3 * 1.1
    Tl = chk["period"]
    d = np.linspace(0, dmax, 50)
    ax.plot(d, d * 1e-3 * (2 * math.pi / Tl) ** 2 / G, color="0.6", lw=0.8, label=f"period of the check {Tl:.2f} s")
    top = max(res.curve.a0_star, frp.curve.a0_star if frp is not None else 0) / G * 1.3
    ax.set(xlim=(0, dmax), ylim=(0, top), xlabel="d* [mm]", ylabel="a* [g]",
           title="capacity against demand (equivalent oscillator)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def _png(fig) -> str:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    return base64.b64encode(buf.getvalue()).decode()


def _checks_table(checks: list[dict]) -> str:
    rows = "".join(
        f"<tr><td>{c['limit_state']} {c['kind']}</td><td>{html.escape(c['where'])}</td>"
        f"<td>{c['capacity_ag'] / G:.3f}</td><td>{c['demand_ag'] / G:.3f}</td><td>{c['safety_index']:.2f}</td>"
        f"<td class='{'yes' if c['verified'] else 'no'}'>{'verified' if c['verified'] else 'NOT verified'}</td></tr>"
        for c in checks)
    return ("<table><tr><th>check</th><th>where</th><th>capacity ag [g]</th><th>site ag [g]</th><th>safety index</th>"
            "<th></th></tr>" + rows + "</table>")


def _figures_table(d: dict) -> str:
    keys = (("alpha0", "alpha0 [-]", 1), ("e_star", "e* [-]", 1), ("M_star", "M* [kg]", 1),
            ("a0_star", "a0* [g]", 1 / G), ("d0_star", "d0* [mm]", 1e3), ("du_star", "d_u* [mm]", 1e3))
    return "<table>" + "".join(f"<tr><td>{lab}</td><td>{d[k] * f:.4g}</td></tr>" for k, lab, f in keys) + "</table>"


def write_report(path: str, label: str, site, mech, res, out: dict, frp=None, frp_out: dict | None = None) -> None:
    """One self-contained HTML page: site, mechanism, figures, checks, the verdict (never overwrites)."""
    chk = next(x for x in res.checks if x["kind"] == "non-linear")
    verdict = (f"<p>Governing safety index <b>{res.safety_index:.2f}</b>: "
               f"<span class='{'yes' if res.verified else 'no'}'>{'verified' if res.verified else 'NOT verified'}"
               f"</span>.</p>")
    parts = [f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>archdem assessment {html.escape(label)}"
             f"</title><style>{_CSS}</style></head><body><h1>Seismic assessment — {html.escape(label)}</h1>", verdict,
             "<p class='meta'>Site: " + html.escape(json.dumps(out["spectrum"])) + "</p>",
             "<p class='meta'>Mechanism: " + html.escape(mech.label) + ", hinges "
             + html.escape(hinges_text(out["mechanism"].get("hinges", [])))
             + "</p>", "<h2>Unreinforced</h2>", _figures_table(out), _checks_table(out["checks"])]
    if frp is not None and frp_out is not None:
        parts += [f"<h2>With FRP strips ({html.escape(frp_out['strips']['face'])}, design force "
                  f"{frp_out['strips']['force_N'] / 1e3:.3g} kN)</h2>",
                  "<p class='meta'>Hinges " + html.escape(hinges_text(frp_out["hinges"]))
                  + "; d0* from the curve of gravity alone (the strips are not shown to last until collapse). "
                    "The DEM does not model the strips.</p>",
                  _figures_table(frp_out), _checks_table(frp_out["checks"])]
    parts += ["<h2>Figures</h2>", f"<img alt='capacity against demand' src='data:image/png;base64,"
              f"{_png(capacity_figure(res, site, frp))}'>",
              f"<img alt='site spectra' src='data:image/png;base64,{_png(spectra_figure(site, chk['damping']))}'>",
              "</body></html>"]
    with atomic_path(path, overwrite=False) as tmp:
        tmp.write_text("".join(parts), encoding="utf-8")
