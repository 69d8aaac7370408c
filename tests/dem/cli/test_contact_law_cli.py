"""The joints on the command line: --joints table-5.1, --kn alone, xi at omega_r; stored with the result."""
import argparse

import pytest

from dem.cli import main
from dem.common.options import contact_law_settings
from dem.core.settings import Settings
from dem.experiments.shake.file import load_shake
from foundation.errors import ArchdemInputError


def _ns(**kw) -> argparse.Namespace:
    base = {"contact_law": None, "kn": None, "youngs": None, "ks": None, "damping_beta": None, "damping_xi": None,
            "joints": None}
    return argparse.Namespace(**(base | kw))


def test_the_law_from_its_options():
    assert contact_law_settings(_ns(), "Sh06-Sd015") == {}
    assert contact_law_settings(_ns(kn=1e8), None) == {"contact_law": "compliant", "kn": 1e8}
    assert contact_law_settings(_ns(kn=1e8, damping_xi=1.0), None) == {"contact_law": "compliant", "kn": 1e8,
                                                                         "damping_xi": 1.0}
    assert contact_law_settings(_ns(joints="table-5.1"), "Sh1-Sd020") == {"contact_law": "compliant", "kn": 4.1e8,
                                                                          "damping_beta": 1.38e-3}


@pytest.mark.parametrize("options, fields", [
    ({"kn": -1.0}, {"contact_law": "compliant", "kn": -1.0}),
    ({"contact_law": "rigid", "kn": 1e8}, {"contact_law": "rigid", "kn": 1e8}),
    ({"contact_law": "compliant"}, {"contact_law": "compliant"}),
    ({"kn": 1e8, "youngs": 1e9}, {"contact_law": "compliant", "kn": 1e8, "youngs": 1e9}),
    ({"kn": 1e8, "damping_xi": 3.0}, {"contact_law": "compliant", "kn": 1e8, "damping_xi": 3.0}),
])
def test_the_command_line_refuses_a_law_in_the_settings_words(options, fields):
    """One set of checks per setting: the options are refused by Settings' own check, with its message."""
    with pytest.raises(ArchdemInputError) as cli:
        contact_law_settings(_ns(**options), None)
    with pytest.raises(ArchdemInputError) as lib:
        Settings(**fields)
    assert str(cli.value) == str(lib.value)


def test_a_shake_on_the_studys_joints_stores_them(tmp_path, capsys):
    # PyBullet: this is about the stored law; MuJoCo's stiff springs cost 40 x its time here
    assert main(["shake", "Sh06-Sd015", "--sine", "4", "--amplitude", "0.2", "--joints", "table-5.1",
                 "--engine", "pybullet", "--out", str(tmp_path), "--json"]) == 0
    (path,) = tmp_path.glob("*.h5")
    st = load_shake(path)["settings"]
    assert (st.contact_law, st.kn, st.damping_beta) == ("compliant", pytest.approx(4.34e8), pytest.approx(2.61e-3))


@pytest.mark.slow
def test_a_campaign_on_the_studys_joints(tmp_path):
    """The campaign's tilt step on Table 5.1's joints: the law in the parameters, lambda within 3 % of the LP."""
    import csv
    import json

    assert main(["campaign", "--specimens", "Sh06-Sd015", "--steps", "tilt", "--joints", "table-5.1", "--quick",
                 "--out", str(tmp_path)]) == 0
    assert json.loads((tmp_path / "campaign.json").read_text())["parameters"]["joints"] == "table-5.1"
    with open(tmp_path / "tilt" / "tilt.csv", newline="") as fh:
        (row,) = list(csv.DictReader(fh))
    assert abs(float(row["err_reference_vs_lp_pct"])) < 3.0


@pytest.mark.slow
def test_the_campaigns_other_simulator_steps_on_the_studys_joints(tmp_path):
    """Lab, map and piers run on the campaign's joints too: every case of their studies stores the law, their
    summaries name it, and the arch on piers keeps within 3 % of the LP at every height."""
    import csv
    import json

    from dem.studies.sweep import load_study

    assert main(["campaign", "--specimens", "Sh06-Sd015", "--steps", "lab,map,piers", "--joints", "table-5.1",
                 "--quick", "--workers", "2", "--out", str(tmp_path)]) == 0
    for study in ("lab-Sh06-Sd015", "map", "piers"):
        records = load_study(tmp_path / "studies" / f"{study}.h5").records
        assert records and all(r.params["settings"]["kn"] == pytest.approx(4.34e8) for r in records), study
    steps = json.loads((tmp_path / "campaign.json").read_text())["steps"]
    assert all(steps[s]["outputs"]["summary"].startswith("Compliant joints") for s in ("lab", "map", "piers"))
    with open(tmp_path / "piers" / "piers.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 4  # the quick study's bare arch and three pier heights: all() of no row would pass
    assert all(abs(float(r["err_dem_vs_lp_pct"])) < 3.0 for r in rows)
