"""The assessment step: the Noh Gumbad vaults against their site, unreinforced and with FRP strips
(docs/physics/assessment.md#7-the-noh-gumbad-example)."""
from __future__ import annotations

from pathlib import Path

from analytic.codes.assessment import NOH_GUMBAD_FRP, monument_site, monument_strips
from dem.common.campaign import CampaignContext, write_csv
from dem.experiments.assessment.run import MonumentAssessment, MonumentSpec, run
from specimens.constants import G
from specimens.monuments import NOH_GUMBAD


def step_assess(ctx: CampaignContext, d: Path) -> dict:
    """The code's kinematic checks of the monument's three configurations, with and without strips."""
    site = monument_site()
    strips = monument_strips()
    design = strips.describe(NOH_GUMBAD.arch.width)
    res = run(MonumentSpec(NOH_GUMBAD, strips, site))
    rows, table = res.assessed, res.rows()
    res.write_csv(d / "assess.csv")
    # every check as the code states it: the index is capacity / demand of the two columns beside it
    write_csv(d / "checks.csv", res.check_rows(), MonumentAssessment.CHECKS_SCHEMA)
    # the calculation of the governing configuration (least governing index), line by line
    gov = res.governing
    write_csv(d / "calculation.csv", res.calculation_rows(), MonumentAssessment.CALCULATION_SCHEMA)
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.experiments.assessment.report_pdf import write_monument_pdf_report

    write_monument_pdf_report(d / "assess.pdf", NOH_GUMBAD, site, strips, project=NOH_GUMBAD.name, overwrite=True,
                              rows=rows)
    findings = []
    for name in NOH_GUMBAD.configurations:
        bare, frp = (next(r for r in table if r["configuration"] == name and r["frp"] == f) for f in (False, True))
        findings.append(f"Noh Gumbad, {name}: lambda {bare['lambda']:.3f} -> {frp['lambda']:.3f} with FRP; governing "
                        f"safety index {min(bare['safety_index_linear'], bare['safety_index_displacement']):.2f} -> "
                        f"{min(frp['safety_index_linear'], frp['safety_index_displacement']):.2f} "
                        f"(site PGA {site.pga / G:.3f} g).")
    return {
        "summary": f"{NOH_GUMBAD.source}. Site: EN 1998-1 type 1, ground A, PGA {site.pga:.3g} m/s^2; linear (q = 2) and "
                   f"displacement (SLV) checks at FC 1.35, and the published table's convention a0*/PGA (activation, "
                   f"no q) beside them; FRP strips {NOH_GUMBAD_FRP[0] / 1e6:g} MPa, "
                   f"{NOH_GUMBAD_FRP[1] * 1e3:g} mm, {NOH_GUMBAD_FRP[2] * 1e3:g} mm on the extrados, design strength "
                   f"{design['design_strength_MPa']:.4g} MPa ({design['governing']} on "
                   f"{design['masonry']['name']}; E_f {design['modulus_GPa']:g} GPa assumed), "
                   f"{design['force_N'] / 1e3:.3g} kN per joint.",
        "tables": [{"name": "assess", "title": "Noh Gumbad: code-based assessment", "csv": "assess/assess.csv"},
                   {"name": "assess_checks", "csv": "assess/checks.csv",
                    "title": "Noh Gumbad: every check as the code states it (safety index = capacity / demand)"},
                   {"name": "assess_calculation", "csv": "assess/calculation.csv",
                    "title": f"Noh Gumbad, calculation of the governing configuration ({gov['configuration']}, "
                             f"{'with' if gov['frp'] else 'without'} FRP): every step with its unit and formula"}],
        "findings": findings,
    }
