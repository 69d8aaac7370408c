"""The printable (PDF) report of a code-based assessment: a title block, the inputs with their units,
the site, every step of the calculation with its formula, value and clause, the verdicts and the
figures of the HTML report (:mod:`dem.experiments.assessment.figure`). Laid out on A4 pages with
matplotlib's PDF backend; plotting and layout only, no physics here (docs/physics/assessment.md)."""
from __future__ import annotations

import datetime
import hashlib
import json
import math
import textwrap
from dataclasses import dataclass, field

from specimens.constants import G
from foundation.io import atomic_path

#: A4 portrait [in], its margins [in], and the fonts' sizes [pt].
PAGE_W, PAGE_H, MARGIN = 8.27, 11.69, 0.7
BODY_PT, TABLE_PT, HEAD_PT = 8.5, 7.0, 12.0
#: Width of a monospace character per point of font size [in], and the line spacing (x the font size).
MONO_W, LEADING = 0.6 / 72, 1.35
#: Resolution of the figures placed on the pages [dpi].
FIGURE_DPI = 200
#: Largest width of a figure on the page [in] (three to a page).
FIGURE_MAX_W = 5.2

PROCEDURE = ("Kinematic analysis of local mechanisms of masonry: NTC 2018 §8.7.1 and Circolare 2019 "
             "§C8.7.1.2; linear (activation, behaviour factor q) and non-linear (displacement) checks.")
STRIPS_DESIGN = "FRP strips designed to CNR-DT 200 R1/2013 (masonry)."
_KIND = {"activation": "activation (no q)", "linear": "linear (q)", "non-linear": "displacement"}
_SITE_UNITS = {"ag": "m/s^2", "pga": "m/s^2", "TB": "s", "TC": "s", "TD": "s", "Tc_star": "s", "t_max": "s",
               "damping": "%"}


def _num(v) -> str:
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, (list, tuple)):
        return ", ".join(_num(x) for x in v)
    if isinstance(v, (int, float)):
        return f"{v:.5g}" if math.isfinite(v) else str(v)
    return "–" if v is None else str(v)


def verdict_word(ok: bool) -> str:
    return "verified" if ok else "NOT verified"


def verdict_rows(checks) -> list[dict]:
    """The verdict table's rows: each check's demand, capacity, safety index, verdict and clause, as
    the library states them (:func:`analytic.codes.assessment.check_rows`)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.codes.assessment import check_rows

    return check_rows(checks)


def site_rows(site) -> list[tuple[str, str, str]]:
    """The site's spectrum, quantity by quantity, with units (accelerations also in g)."""
    d = {**site.describe(), "pga": site.pga}
    rows = []
    for k, v in d.items():
        unit = _SITE_UNITS.get(k, "-" if isinstance(v, (int, float)) and not isinstance(v, bool) else "")
        val = _num(v) + (f"  ({v / G:.4g} g)" if unit == "m/s^2" and isinstance(v, (int, float)) else "")
        rows.append((k, val, unit))
    return rows


def _arch_rows(arch) -> list[tuple[str, object, str]]:
    rows = []
    for name, unit in (("e", "m"), ("t", "m"), ("Rp", "m"), ("Rc", "m"), ("width", "m"), ("span", "m"), ("rise", "m")):
        try:
            v = getattr(arch, name)
        except (AttributeError, ValueError):
            continue
        if isinstance(v, (int, float)):
            rows.append((f"arch {name}", v, unit))
    return rows


#: The command's options shown among the inputs: (option, label, unit).
_OPTIONS = (("pier_height", "piers: height", "m"), ("pier_width", "piers: width", "m"),
            ("pier_courses", "piers: courses", "-"), ("density", "density", "kg/m^3"),
            ("voussoirs", "voussoirs", "-"), ("FC", "confidence factor FC", "-"), ("q", "behaviour factor q", "-"),
            ("limit_state", "limit state", ""), ("sld_ag", "SLD hazard ag", "g"), ("z_ratio", "height: z/H", "-"),
            ("T1", "height: building period T1", "s"), ("floors", "height: floors", "-"),
            ("building_damping", "height: building damping", "%"),
            ("frp", "FRP: strength, thickness, width[, design]", "MPa, mm, mm[, MPa]"),
            ("frp_modulus", "FRP: modulus E_f", "GPa"), ("frp_face", "FRP: face", ""),
            ("frp_fibre", "FRP: fibre", ""), ("frp_exposure", "FRP: exposure", ""),
            ("frp_application", "FRP: application", ""), ("masonry", "masonry f_m, f_mt (or type)", "MPa"),
            ("tie", "tie: height, area, f_y[, prestress]", "m, mm^2, MPa[, kN]"), ("records", "records", ""),
            ("engine", "engine of the records", ""))


def bond_rows(strips) -> list[tuple[str, object, str]]:
    """The guideline's bond factors the ``strips`` were designed with (none without debonding, i.e.
    without a masonry), each marked "unverified default" or "set by the user"."""
    if strips is None or strips.masonry is None:
        return []
    return [(f"FRP bond factor {d['symbol']}", f"{d['value']:g} ({d['source']})", d["unit"])
            for k, d in strips.bond.describe().items()
            if k != "fmt_ratio" or strips.masonry.name != "given"]  # given f_mtm: no ratio used


def command_inputs(args, arch, strips=None) -> list[tuple[str, object, str]]:
    """The inputs of ``archdem assess`` with their units: the arch's geometry and the options given
    (those left unset are left out; the spectrum's are in the site table); with ``strips`` designed on
    a masonry, the bond factors they used (:func:`bond_rows`)."""
    rows = [("structure", getattr(args, "id", None) or "parametric", "")] + _arch_rows(arch)
    for opt, label, unit in _OPTIONS:
        v = getattr(args, opt, None)
        if v is None or v is False or v == []:
            continue
        if opt.startswith("frp_") and getattr(args, "frp", None) is None:
            continue
        if opt == "engine" and not getattr(args, "records", None):
            continue
        if opt == "building_damping" and getattr(args, "z_ratio", None) is None:
            continue
        rows.append((label, ", ".join(map(str, v)) if isinstance(v, list) else v, unit))
    return rows + bond_rows(strips)


def inputs_hash(label: str, inputs, spectrum: dict) -> str:
    """16 hex digits of the SHA-256 of the inputs and the site, as canonical JSON."""
    blob = json.dumps({"label": label, "inputs": [list(r) for r in inputs], "spectrum": spectrum}, sort_keys=True,
                      separators=(",", ":"), default=str)
    return hashlib.sha256(blob.encode()).hexdigest()[:16]


def archdem_version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("archdem")
    except PackageNotFoundError:
        return "unknown"


# ---- layout: blocks placed top-down on A4 pages, a new page when one is full ----

@dataclass
class _Line:
    text: str
    size: float
    mono: bool = False
    bold: bool = False
    color: str = "black"
    x: float = 0.0  # inches from the left margin


@dataclass
class _Page:
    items: list = field(default_factory=list)  # (y from the top margin [in], _Line) or (y, image, height)
    y: float = 0.0


class _Layout:
    def __init__(self) -> None:
        self.pages = [_Page()]
        self.usable = PAGE_H - 2 * MARGIN - 0.35  # the footer's room

    @property
    def page(self) -> _Page:
        return self.pages[-1]

    def need(self, h: float) -> None:
        if self.page.y + h > self.usable and self.page.items:
            self.pages.append(_Page())

    def new_page(self) -> None:
        if self.page.items:
            self.pages.append(_Page())

    def lines(self, lines: list[_Line], gap: float = 0.0) -> None:
        """Lines sharing one row each (several _Line at one y: cells of a table row, as a list)."""
        for ln in lines:
            group = ln if isinstance(ln, list) else [ln]
            h = max(x.size for x in group) * LEADING / 72
            self.need(h)
            for x in group:
                self.page.items.append((self.page.y, x))
            self.page.y += h
        self.page.y += gap

    def heading(self, text: str, size: float = HEAD_PT) -> None:
        # a heading never ends a page: room for it and the first lines of what it heads
        self.need((2 * size + 6 * TABLE_PT) * LEADING / 72)
        self.page.y += 0.08
        width = int((PAGE_W - 2 * MARGIN) / (0.62 * size / 72))
        self.lines([_Line(t, size, bold=True, color="#5a4620") for t in textwrap.wrap(text, width)], gap=0.04)

    def paragraph(self, text: str, size: float = BODY_PT, **kw) -> None:
        width = int((PAGE_W - 2 * MARGIN) / (0.5 * size / 72))
        self.lines([_Line(t, size, **kw) for t in textwrap.wrap(text, width)] or [_Line("", size)], gap=0.05)

    def table(self, header: list[str], rows: list[list[str]], widths: list[int], colors: dict | None = None) -> None:
        """Monospace columns ``widths`` characters wide; long cells wrap inside their column; ``colors``:
        (row, column) -> colour."""
        colors = colors or {}
        cw = MONO_W * TABLE_PT
        xs = [sum(widths[:i]) * cw for i in range(len(widths))]

        def row_lines(cells, bold=False, r=None):
            wrapped = [textwrap.wrap(str(c), max(1, w - 2)) or [""] for c, w in zip(cells, widths)]
            out = []
            for k in range(max(len(w) for w in wrapped)):
                out.append([_Line(w[k], TABLE_PT, mono=True, bold=bold, x=x,
                                  color=colors.get((r, j), "black") if r is not None else "#5a4620")
                            for j, (w, x) in enumerate(zip(wrapped, xs)) if k < len(w)])
            return out

        self.need(3 * TABLE_PT * LEADING / 72)
        self.lines(row_lines(header, bold=True))
        for r, cells in enumerate(rows):
            ls = row_lines(cells, r=r)
            pages = len(self.pages)
            self.need(len(ls) * TABLE_PT * LEADING / 72)
            if len(self.pages) > pages:  # the header again on a new page
                self.lines(row_lines(header, bold=True))
            self.lines(ls)
        self.page.y += 0.08

    def image(self, img, caption: str) -> None:
        h_px, w_px = img.shape[:2]
        w = min(FIGURE_MAX_W, w_px / FIGURE_DPI)
        h = w * h_px / w_px
        self.need(h + 0.3)
        self.page.items.append((self.page.y, img, w, h))
        self.page.y += h + 0.05
        self.lines([_Line(caption, BODY_PT - 0.5, color="#444")], gap=0.15)


def _raster(fig):
    """A matplotlib figure as an RGBA array at :data:`FIGURE_DPI`."""
    import io

    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from matplotlib.image import imread

    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=FIGURE_DPI, bbox_inches="tight")
    buf.seek(0)
    return imread(buf)


def _render(layout: _Layout, path, footer: str, metadata: dict, overwrite: bool) -> int:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from matplotlib import rc_context
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.figure import Figure

    n = len(layout.pages)
    top = PAGE_H - MARGIN
    with rc_context({"pdf.fonttype": 42}), atomic_path(path, overwrite=overwrite) as tmp:
        with PdfPages(tmp, metadata=metadata) as pdf:
            for k, page in enumerate(layout.pages, 1):
                fig = Figure(figsize=(PAGE_W, PAGE_H))
                for item in page.items:
                    y = top - item[0]
                    if isinstance(item[1], _Line):
                        ln = item[1]
                        fig.text((MARGIN + ln.x) / PAGE_W, y / PAGE_H, ln.text, fontsize=ln.size, va="top", ha="left",
                                 family="monospace" if ln.mono else "sans-serif",
                                 weight="bold" if ln.bold else "normal", color=ln.color)
                    else:
                        img, w, h = item[1:]
                        ax = fig.add_axes(((PAGE_W - w) / 2 / PAGE_W, (y - h) / PAGE_H, w / PAGE_W, h / PAGE_H))
                        ax.imshow(img, interpolation="antialiased")
                        ax.set_axis_off()
                fig.add_artist(_rule(fig, MARGIN - 0.25))
                fig.text(MARGIN / PAGE_W, (MARGIN - 0.35) / PAGE_H, footer, fontsize=7, color="#555", va="top")
                fig.text((PAGE_W - MARGIN) / PAGE_W, (MARGIN - 0.35) / PAGE_H, f"page {k} of {n}", fontsize=7,
                         color="#555", va="top", ha="right")
                pdf.savefig(fig)
    return n


def _rule(fig, y: float):
    from matplotlib.lines import Line2D

    return Line2D([MARGIN / PAGE_W, 1 - MARGIN / PAGE_W], [y / PAGE_H] * 2, transform=fig.transFigure, lw=0.5,
                  color="#8a6d3b")


# ---- the report's sections ----

def _title_block(L: _Layout, label: str, fields: list[tuple[str, str]], verdicts: list[tuple[str, float, bool, str]]) -> None:
    L.heading(f"Seismic assessment — {label}", 16)
    L.table(["", ""], [[k, v] for k, v in fields], [24, 80])
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.codes.assessment import index_text

    for what, si, ok, gov in verdicts:
        L.lines([[_Line(verdict_word(ok), 10.5, bold=True, color="#070" if ok else "#a00"),
                  _Line(f"{what}: governing safety index {index_text(si)} ({gov})", 10.5, bold=True, x=1.35)]],
                gap=0.03)
    L.page.y += 0.06
    L.paragraph(PROCEDURE, BODY_PT - 0.5, color="#444")


def _steps_table(L: _Layout, trail: list[dict]) -> None:
    """The steps with their formula, value and unit, and their clause where the trail records one."""
    if any(s.get("clause") for s in trail):
        L.table(["quantity", "value", "unit", "formula", "clause"],
                [[s["symbol"], _num(s["value"]), s["unit"], s["formula"], s.get("clause") or ""] for s in trail],
                [30, 16, 14, 42, 14])
    else:
        L.table(["quantity", "value", "unit", "formula"],
                [[s["symbol"], _num(s["value"]), s["unit"], s["formula"]] for s in trail], [32, 18, 16, 50])


def _verdict_table(L: _Layout, checks: list[dict], limit_states: dict | None) -> None:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.codes.assessment import index_text, quantity_text

    rows = verdict_rows(checks)
    L.table(["check", "where", "demand", "capacity", "safety index", "verdict", "clause"],
            [[f"{r['limit_state']} {r['check']}", r["where"],
              f"{r['demand_symbol']} = {quantity_text(r['demand'], r['unit'])}",
              f"{r['capacity_symbol']} = {quantity_text(r['capacity'], r['unit'])}", index_text(r["safety_index"]),
              verdict_word(r["verified"]), r["clause"]] for r in rows],
            [17, 8, 22, 22, 8, 13, 26], {(i, 5): "#070" if r["verified"] else "#a00" for i, r in enumerate(rows)})
    for ls, d in (limit_states or {}).items():
        L.paragraph(f"{ls}: governing {_KIND.get(d['governing'], d['governing'])}, safety index "
                    f"{index_text(d['safety_index'])} — {verdict_word(d['verified'])}", BODY_PT)


def _summary_table(L: _Layout, d: dict) -> None:
    keys = (("alpha0", "alpha0", "-", 1), ("M_star", "M*", "kg", 1), ("e_star", "e*", "-", 1),
            ("a0_star", "a0*", "g", 1 / G), ("d0_star", "d0*", "mm", 1e3), ("du_star", "d_u*", "mm", 1e3))
    L.table(["quantity", "value", "unit"],
            [[lab, "–" if d.get(k) is None else f"{d[k] * f:.4g}", u] for k, lab, u, f in keys], [30, 16, 14])


def _layout(label: str, site, mech, res, out: dict, frp, frp_out: dict | None, fields: list, inputs,
            extra=None) -> _Layout:
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.figure import (
        capacity_figure,
        hinges_text,
        mechanism_figure,
        spectra_figure,
        strengthening_text,
    )

    strengthened = frp is not None and frp_out is not None
    verdicts = [("Unreinforced", res.safety_index, res.verified, out["governing_check"])]
    if strengthened:
        verdicts.append(("Strengthened", frp.safety_index, frp.verified, frp_out["governing_check"]))
    L = _Layout()
    _title_block(L, label, fields, verdicts)
    L.heading("1. Inputs")
    L.table(["input", "value", "unit"], [[k, _num(v), u] for k, v, u in inputs], [44, 40, 20])
    L.heading("2. Site (elastic spectrum)")
    L.table(["quantity", "value", "unit"], site_rows(site), [30, 40, 20])
    if extra is not None:
        extra(L)
    L.heading("3. Unreinforced mechanism")
    L.paragraph(f"Mechanism: {mech.label}; hinges {hinges_text(out['mechanism'].get('hinges', []))}.")
    _summary_table(L, out)
    L.heading("3.1 Calculation, step by step", 10)
    _steps_table(L, out["trail"])
    if strengthened:
        L.heading(f"4. Strengthened: {strengthening_text(frp_out)}")
        L.paragraph(f"Hinges {hinges_text(frp_out['hinges'])}; d0* from the curve of gravity alone (the "
                    "strengthening is not shown to last until collapse). The DEM does not model the strengthening.")
        _summary_table(L, frp_out)
        L.heading("4.1 Calculation, step by step", 10)
        _steps_table(L, frp_out["trail"])
        if frp_out.get("strips"):
            L.heading("4.2 The strips' design", 10)
            L.paragraph(STRIPS_DESIGN)
            _steps_table(L, [{"symbol": k, **v} for k, v in frp_out["strips"]["design"].items()])
    n = 5 if strengthened else 4
    L.new_page()
    L.heading(f"{n}. Verdicts")
    L.heading("Unreinforced", 10)
    _verdict_table(L, out["checks"], out["limit_states"])
    if strengthened:
        L.heading("Strengthened", 10)
        _verdict_table(L, frp_out["checks"], frp_out["limit_states"])
    L.paragraph("Conventions: the activation check has no behaviour factor (SLD: against the SLD hazard); the "
                "linear check divides the activation by q against the SLV hazard; an index quoted as a0*/PGA is the "
                "activation against the life-safety hazard's PGA on rock, reported as a convention, not a code check.",
                BODY_PT - 0.5, color="#444")
    chk = next((x for x in res.checks if x["kind"] == "non-linear"), None)
    L.new_page()
    L.heading(f"{n + 1}. Figures")
    L.image(_raster(capacity_figure(res, site, frp)), "Capacity curves against the site's demand (equivalent "
                                                      "oscillator, acceleration-displacement form).")
    L.image(_raster(spectra_figure(site, chk["damping"] if chk is not None else 5.0)),
            "The site's acceleration and displacement spectra at 5 % and at the mechanism's damping.")
    L.image(_raster(mechanism_figure(mech, "unreinforced mechanism")),
            "The unreinforced mechanism: centroids at rest and displaced, virtual displacements per unit rotation.")
    return L


def _fields(label, project, engineer, date, digest) -> list[tuple[str, str]]:
    return [("project", project), ("engineer", engineer), ("date", date), ("structure", label),
            ("archdem version", archdem_version()), ("inputs hash (SHA-256)", digest)]


def write_pdf_report(path, label: str, site, mech, res, out: dict, frp=None, frp_out: dict | None = None,
                     project: str = "-", engineer: str = "-", inputs=None, date: str | None = None,
                     overwrite: bool = False) -> int:
    """The printable report of :func:`dem.experiments.assessment.figure.write_report`'s assessment
    (same arguments) on A4 pages; ``inputs``: rows (name, value, unit) of the inputs (default: the
    assessment's factors); the hash is of the inputs and the site. Never overwrites unless
    ``overwrite``. Returns the number of pages."""
    if inputs is None:
        inputs = [("structure", label, ""), ("confidence factor FC", out.get("FC"), "-"),
                  ("limit state", out.get("limit_state"), "")]
    inputs = [tuple(r) for r in inputs]
    digest = inputs_hash(label, inputs, site.describe())
    date = date or datetime.date.today().isoformat()
    L = _layout(label, site, mech, res, out, frp, frp_out, _fields(label, project, engineer, date, digest), inputs)
    return _render(L, path, f"archdem {archdem_version()} — {label} — {project} — inputs {digest}",
                   {"Title": f"Seismic assessment — {label}", "Author": engineer, "Subject": project,
                    "Creator": f"archdem {archdem_version()}"}, overwrite)


def monument_governing(monument, site, strips, FC: float, q: float, limit_state: str = "SLV", rows=None,
                       height=None, sld_site=None):
    """The governing configuration of a monument (the least unreinforced safety index) assessed in full,
    unreinforced and with ``strips``: ``(rows, name, mech, res, out, frp, frp_out)``, the last five as
    :func:`write_pdf_report` takes them (``rows``: :func:`analytic.codes.assessment.assess_monument`'s)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.codes.assessment import assess, assess_monument
    from analytic.codes.frp import strengthened_collapse

    if rows is None:
        rows = assess_monument(monument, site, strips, FC, q, limit_state, height=height, sld_site=sld_site)
    name = min((r for r in rows if not r["frp"] and not r.get("tie")), key=lambda r: r["safety_index"])["configuration"]
    done = {}
    for s in (None, strips):
        # loads along +x, as assess_monument does
        sc = strengthened_collapse(monument.arch, s, monument.density, monument.configurations[name], load_sign=1)
        r = assess(sc.mechanism, site, FC, q, limit_state, height, alpha0=sc.lam,
                   extra_force=sc.extra_force if s is not None else None, sld_site=sld_site)
        done[s is not None] = (sc, r)
    (sc0, res), (sc1, frp) = done[False], done[True]
    out = {"mechanism": sc0.mechanism.summary(), **res.describe()}
    frp_out = {"strips": strips.describe(monument.arch.width), "hinges": sc1.mechanism.summary()["hinges"],
               "tie": None, **frp.describe()}
    return rows, name, sc0.mechanism, res, out, frp, frp_out


def write_monument_pdf_report(path, monument, site, strips, FC: float | None = None, q: float | None = None,
                              limit_state: str = "SLV", project: str = "-", engineer: str = "-",
                              date: str | None = None, overwrite: bool = False, rows: list | None = None,
                              height=None, sld_site=None) -> int:
    """The printable report of a monument (:mod:`specimens.monuments`): every configuration's row,
    then the full calculation of the governing one (the least unreinforced safety index), unreinforced
    and with ``strips``; ``rows``: :func:`analytic.codes.assessment.assess_monument`'s, when at hand."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.codes.kinematic import CONFIDENCE_FACTORS, Q_MASONRY

    FC = CONFIDENCE_FACTORS["LC1"] if FC is None else FC
    q = Q_MASONRY if q is None else q
    rows, name, mech, res, out, frp, frp_out = monument_governing(monument, site, strips, FC, q, limit_state, rows,
                                                                  height, sld_site)
    inputs = ([("structure", monument.name, ""), ("source", monument.source, "")] + _arch_rows(monument.arch)
              + [("density", monument.density, "kg/m^3"), ("configuration assessed in full", name, "")]
              + [(f"piers of '{k}': height, width", "none" if p is None else f"{p.height:g}, {p.width:g}", "m")
                 for k, p in monument.configurations.items()]
              + [("confidence factor FC", FC, "-"), ("behaviour factor q", q, "-"), ("limit state", limit_state, ""),
                 ("FRP: strength, thickness, width", f"{strips.strength / 1e6:g}, {strips.thickness * 1e3:g}, "
                                                     f"{strips.width * 1e3:g}", "MPa, mm, mm"),
                 ("FRP: face", strips.face, "")] + bond_rows(strips)
              + ([] if height is None else [("height: z/H, T1, floors", f"{height.z_ratio:g}, {height.T1:g}, "
                                                                          f"{height.floors}", "-, s, -")])
              + ([] if sld_site is None else [("SLD hazard ag", sld_site.ag, "m/s^2")]))

    def configurations(L: _Layout) -> None:
        L.heading("Configurations (each unreinforced and strengthened)")
        L.table(["configuration", "with", "lambda", "e*", "a0* [g]", "d0* [mm]", "a0*/PGA", "SI lin", "SI disp",
                 "verdict"],
                [[r["configuration"], "FRP" if r["frp"] else "tie" if r.get("tie") else "none", f"{r['lambda']:.4f}",
                  f"{r['e_star']:.3f}",
                  f"{r['a0_star'] / G:.4f}", f"{r['d0_star'] * 1e3:.4g}", _num(r["activation_over_pga"]),
                  _num(r["safety_index_linear"]), _num(r["safety_index_displacement"]), verdict_word(r["verified"])]
                 for r in rows], [20, 7, 9, 8, 9, 9, 9, 9, 9, 14],
                {(i, 9): "#070" if r["verified"] else "#a00" for i, r in enumerate(rows)})

    label = f"{monument.name} ({name})"
    digest = inputs_hash(label, inputs, site.describe())
    date = date or datetime.date.today().isoformat()
    L = _layout(label, site, mech, res, out, frp, frp_out, _fields(label, project, engineer, date, digest),
                inputs, extra=configurations)
    return _render(L, path, f"archdem {archdem_version()} — {label} — {project} — inputs {digest}",
                   {"Title": f"Seismic assessment — {label}", "Author": engineer, "Subject": project,
                    "Creator": f"archdem {archdem_version()}"}, overwrite)
