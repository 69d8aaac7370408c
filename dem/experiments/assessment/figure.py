"""Figures and the one-page HTML report of a code-based assessment. Plotting only; no physics here."""
from __future__ import annotations

import base64
import html
import io
import math

import numpy as np
from matplotlib.figure import Figure

from analytic.codes.assessment import check_rows, index_text, quantity_text, site_table
from analytic.motions.spectra import rebuild
from specimens.constants import G
from foundation.io import atomic_path

_CSS = ("body{font-family:system-ui,sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;color:#222}"
        "h1{border-bottom:2px solid #8a6d3b}table{border-collapse:collapse;font-size:13px;margin:0.8em 0}"
        "th,td{border:1px solid #bbb;padding:3px 7px;text-align:right}th{background:#f3efe6}"
        "td:first-child,th:first-child{text-align:left}img{max-width:480px;width:100%;border:1px solid #ddd;margin:0.3em}"
        ".no{color:#a00;font-weight:bold}.yes{color:#070;font-weight:bold}.meta{font-size:12px;color:#555;"
        "overflow-wrap:anywhere}.wrap{max-width:100%;overflow-x:auto}table.calc td{text-align:left}"
        "table.calc td:nth-child(2){text-align:right;white-space:nowrap}")


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
    for r, col, lab in ((res, "k", "unreinforced"), (frp, "C0", "strengthened")):
        if r is None:
            continue
        c = r.curve
        ax.plot(c.d_star * 1e3, c.a_star / G, color=col, lw=2, label=f"capacity, {lab}")
        ax.plot([0, c.d0_star * 1e3], [c.a0_star / G, 0], color=col, lw=0.8, ls=":")
        for chk in (x for x in r.checks if x["kind"] == "non-linear"):
            ax.plot([chk["d_u_star"] * 1e3], [chk["a_u_star"] / G], "o", color=col)
            ax.annotate(f"{chk['limit_state']} d_u*", (chk["d_u_star"] * 1e3, chk["a_u_star"] / G), fontsize=8,
                        xytext=(4, 4), textcoords="offset points")
    chk = next((x for x in res.checks if x["kind"] == "non-linear"), None)
    xi = chk["damping"] if chk is not None else 5.0
    dem = rebuild(site, damping=xi)
    T = np.linspace(1e-3, dem.t_max, 600)
    ax.plot(dem.SDe(T) * 1e3, dem.Se(T) / G, "C3--", label=f"site demand, {xi:g} % damping")
    dmax = max(res.curve.d0_star, frp.curve.d0_star if frp is not None else 0) * 1e3 * 1.1
    if chk is not None:
        Tl = chk["period"]
        d = np.linspace(0, dmax, 50)
        ax.plot(d, d * 1e-3 * (2 * math.pi / Tl) ** 2 / G, color="0.6", lw=0.8, label=f"period of the check {Tl:.2f} s")
    for c in res.checks:  # the activation and linear checks' demands: horizontal lines a = demand / q
        if c["kind"] in ("activation", "linear"):
            ax.axhline(c["demand_acceleration"] / c.get("q", 1.0) / G, color="C2" if c["kind"] == "activation" else "C1",
                       lw=0.8, ls="-.", label=f"{c['limit_state']} {c['kind']}: demand / q")
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


def _checks_table(checks: list[dict], limit_states: dict | None = None) -> str:
    """The checks as the code states them (:func:`analytic.codes.assessment.check_rows`): demand and
    capacity as the clause compares them, the index capacity / demand, the verdict and the clause; each
    limit state's governing check below."""
    rows = "".join(
        f"<tr><td>{html.escape(r['limit_state'] + ' ' + r['check'])}</td><td>{html.escape(r['where'])}</td>"
        f"<td>{html.escape(r['demand_symbol'] + ' ' + quantity_text(r['demand'], r['unit']))}</td>"
        f"<td>{html.escape(r['capacity_symbol'] + ' ' + quantity_text(r['capacity'], r['unit']))}</td>"
        f"<td>{index_text(r['safety_index'])}</td>"
        f"<td class='{'yes' if r['verified'] else 'no'}'>{r['verdict']}</td><td>{html.escape(r['clause'])}</td></tr>"
        for r in check_rows(checks))
    gov = "".join(f"<li>{ls}: governing {html.escape(d['governing'])}, safety index {index_text(d['safety_index'])} "
                  f"({'verified' if d['verified'] else 'not verified'})</li>" for ls, d in (limit_states or {}).items())
    return ("<div class='wrap'><table><tr><th>check</th><th>where</th><th>demand</th><th>capacity</th>"
            "<th>safety index (capacity / demand)</th><th>verdict</th><th>clause</th></tr>" + rows + "</table></div>"
            + (f"<ul>{gov}</ul>" if gov else ""))


def _site_table(site) -> str:
    """The site's spectrum as a table (:func:`analytic.codes.assessment.site_table`), not raw JSON."""
    return ("<table>" + "".join(f"<tr><td>{html.escape(k)}</td><td>{html.escape(v)}</td></tr>"
                                for k, v in site_table(site)) + "</table>")


def _calculation(trail: list[dict]) -> str:
    """The trail as a table an engineer follows line by line."""
    def val(v):
        if isinstance(v, bool):
            return "yes" if v else "no"
        if isinstance(v, (list, tuple)):
            return ", ".join(f"{x:.4g}" for x in v)
        return "–" if v is None else f"{v:.5g}"

    rows = "".join(f"<tr><td>{html.escape(s['symbol'])}</td><td>{val(s['value'])}</td><td>{html.escape(s['unit'])}</td>"
                   f"<td>{html.escape(s['formula'])}</td></tr>" for s in trail)
    return ("<div class='wrap'><table class='calc'><tr><th>quantity</th><th>value</th><th>unit</th><th>formula</th></tr>"
            + rows + "</table></div>")


def mechanism_figure(mech, title: str):
    """The mechanism at rest and displaced, with each body's virtual displacement (centroid, arrows)."""
    fig = Figure(figsize=(6, 3.6))
    ax = fig.subplots()
    phi = 0.25 * mech.phi_cr if mech.phi_cr > 0 else 0.05
    rest, moved = mech.body_states(0.0), mech.body_states(phi)
    size = max(1e-9, max(abs(b.x) for b in rest) + max(abs(b.y) for b in rest))
    scale = 0.25 * size / max(1e-12, max(math.hypot(b.dx, b.dy) for b in rest))
    pts = getattr(mech, "points", None) or [getattr(mech, "pivot", (0.0, 0.0))]
    ax.plot([p[0] for p in pts], [p[1] for p in pts], "ks", ms=5, label="hinges")
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    for k, (b0, b1) in enumerate(zip(rest, moved)):
        tip = (b0.x + scale * b0.dx, b0.y + scale * b0.dy)
        xs += [b0.x, b1.x, tip[0]]
        ys += [b0.y, b1.y, tip[1]]
        ax.plot([b0.x], [b0.y], "o", color=f"C{k}")
        ax.plot([b1.x], [b1.y], "x", color=f"C{k}")
        ax.annotate("", tip, (b0.x, b0.y), arrowprops={"arrowstyle": "->", "color": f"C{k}"}, annotation_clip=False)
        ax.annotate(f"body {k}: ({b0.dx:.3g}, {b0.dy:.3g}) m/rad", (b0.x, b0.y), fontsize=7, xytext=(4, -10),
                    textcoords="offset points")
    pad = 0.08 * size
    ax.set_xlim(min(xs) - pad, max(xs) + 3 * pad)
    ax.set_ylim(min(ys) - pad, max(ys) + pad)
    ax.set_aspect("equal")
    ax.set(xlabel="x [m]", ylabel="y [m]", title=f"{title}\ncentroids at rest (o) and at phi = {phi:.3g} rad (x); "
                                               f"virtual displacements per unit phi (arrows)")
    ax.title.set_fontsize(8)
    fig.tight_layout()
    return fig


def _figures_table(d: dict) -> str:
    keys = (("alpha0", "alpha0 [-]", 1), ("e_star", "e* [-]", 1), ("M_star", "M* [kg]", 1),
            ("a0_star", "a0* [g]", 1 / G), ("d0_star", "d0* [mm]", 1e3), ("du_star", "d_u* [mm]", 1e3))
    return "<table>" + "".join(f"<tr><td>{lab}</td><td>{d[k] * f:.4g}</td></tr>" for k, lab, f in keys) + "</table>"


def strengthening_text(frp_out: dict) -> str:
    """What strengthens the mechanism, in words: the strips (face, design strength, force per joint) and
    the tie (height, yield force)."""
    what = []
    if frp_out.get("strips"):
        st = frp_out["strips"]
        what.append(f"FRP strips on the {st['face']}, f_fd {st['design_strength_MPa']:.4g} MPa ({st['governing']}), "
                    f"{st['force_N'] / 1e3:.3g} kN per joint")
    if frp_out.get("tie"):
        t = frp_out["tie"]
        what.append(f"a tie at {t['height_m']:g} m yielding at {t['yield_force_kN']:.4g} kN")
    return "; ".join(what)


def write_report(path: str, label: str, site, mech, res, out: dict, frp=None, frp_out: dict | None = None) -> None:
    """One self-contained HTML page: site, mechanism, figures, checks, the verdict (never overwrites)."""
    chk = next((x for x in res.checks if x["kind"] == "non-linear"), None)
    verdict = (f"<p>Governing safety index <b>{index_text(res.safety_index)}</b> ({html.escape(out['governing_check'])}): "
               f"<span class='{'yes' if res.verified else 'no'}'>{'verified' if res.verified else 'not verified'}"
               f"</span>.</p>")
    parts = [f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>archdem assessment {html.escape(label)}"
             f"</title><style>{_CSS}</style></head><body><h1>Seismic assessment — {html.escape(label)}</h1>", verdict,
             "<h2>Site</h2>", _site_table(site),
             "<p class='meta'>Mechanism: " + html.escape(mech.label) + ", hinges "
             + html.escape(hinges_text(out["mechanism"].get("hinges", [])))
             + "</p>", "<h2>Unreinforced</h2>", _figures_table(out), _checks_table(out["checks"], out["limit_states"]),
             "<p class='meta'>Each check compares a demand with a capacity as its clause does; the safety index "
             "is capacity / demand and the check passes at 1 or more. The activation check has no behaviour factor "
             "(SLD: against the SLD hazard); the linear check compares q a0* with the SLV hazard's ag S; an index "
             "quoted as a0*/PGA is the activation against the life-safety hazard, reported as a convention, not a "
             "code check.</p>"]
    if frp is not None and frp_out is not None:
        parts += [f"<h2>Strengthened: {html.escape(strengthening_text(frp_out))}</h2>",
                  "<p class='meta'>Hinges " + html.escape(hinges_text(frp_out["hinges"]))
                  + "; d0* from the curve of gravity alone (the strengthening is not shown to last until collapse). "
                    "The DEM does not model the strengthening.</p>",
                  _figures_table(frp_out), _checks_table(frp_out["checks"], frp_out["limit_states"])]
    parts += ["<h2>Figures</h2>", f"<img alt='capacity against demand' src='data:image/png;base64,"
              f"{_png(capacity_figure(res, site, frp))}'>",
              f"<img alt='site spectra' src='data:image/png;base64,"
              f"{_png(spectra_figure(site, chk['damping'] if chk is not None else 5.0))}'>",
              f"<img alt='virtual displacements' src='data:image/png;base64,"
              f"{_png(mechanism_figure(mech, 'unreinforced mechanism'))}'>"]
    gov, gov_out, gov_name = ((frp, frp_out, "strengthened") if frp is not None and frp_out is not None
                              else (res, out, "unreinforced"))
    parts += [f"<h2>Calculation ({gov_name} mechanism)</h2>",
              "<p class='meta'>Every quantity of the verification in the order it is written, with its unit and "
              "the formula it comes from (docs/physics/assessment.md).</p>", _calculation(gov_out["trail"])]
    if gov is frp:
        parts += ["<h3>Unreinforced mechanism</h3>", _calculation(out["trail"])]
        if frp_out.get("strips"):
            d = frp_out["strips"]["design"]
            parts += ["<h3>The strips' design</h3>", _calculation([{"symbol": k, **v} for k, v in d.items()])]
    parts += ["</body></html>"]
    with atomic_path(path, overwrite=False) as tmp:
        tmp.write_text("".join(parts), encoding="utf-8")
