"""The compliant contact law: its settings, its point stiffnesses and omega_r against hand computations."""
import math

import pytest

from dem.core.contact import (
    highest_frequency,
    normal_stiffness,
    point_stiffness,
    rayleigh_beta,
    rotational_impact_frequency,
)
from dem.core.model import as_model, single_block
from dem.core.settings import Settings
from foundation.errors import ArchdemInputError


@pytest.mark.parametrize("kw, msg", [
    ({"contact_law": "compliant"}, "needs the normal joint stiffness kn > 0"),
    ({"contact_law": "compliant", "kn": -1.0}, "kn must be a number >= 0"),
    ({"contact_law": "compliant", "kn": float("inf")}, "kn must be a number >= 0"),
    ({"contact_law": "compliant", "kn": 1e8, "damping_xi": 2.5}, "outside 0-2"),
    ({"contact_law": "compliant", "kn": 1e8, "damping_xi": 1.0, "damping_beta": 1e-3}, "not both"),
    ({"kn": 1e8}, "belong to the compliant contact law"),
    ({"contact_law": "soft"}, "is not one of rigid, compliant"),
    ({"contact_law": "compliant", "kn": 1e8, "youngs": 1e9}, "as kn or as the blocks' Young's modulus, not both"),
    ({"contact_law": "compliant", "youngs": -1e9}, "youngs must be a number >= 0"),
])
def test_bad_contact_law_settings(kw, msg):
    with pytest.raises(ArchdemInputError, match=msg):
        Settings(**kw)


def test_the_law_round_trips_through_a_result_file():
    s = Settings(contact_law="compliant", kn=4.34e8, damping_xi=1.0)
    assert Settings.from_dict(s.to_dict()) == s and Settings().contact_law == "rigid"


def test_a_blocks_points_omega_r_and_xi():
    """Block b x h x w: each corner carries k_n b w / 4; omega_r = sqrt(k_n A b^2 / J_o) about a base
    corner, J_o = m (b^2 + h^2) / 3; xi at omega_r gives beta_R = 2 xi / omega_r."""
    b, h, w, rho, kn = 0.2, 0.4, 0.1, 500.0, 1e7
    model = single_block(b, h, w, rho)
    m = rho * b * h * w
    assert point_stiffness(model, kn) == pytest.approx([kn * b * w / 4])
    w_r = math.sqrt(kn * b * w * b * b / (m * (b * b + h * h) / 3))
    assert rotational_impact_frequency(model, kn) == pytest.approx(w_r, rel=1e-12)
    s = Settings(contact_law="compliant", kn=kn, damping_xi=0.5)
    assert rayleigh_beta(s, model) == pytest.approx(1.0 / w_r, rel=1e-12)
    # the estimate bounds the block's own highest frequency (vertical sqrt(k_n A / m) at most)
    assert highest_frequency(model, kn) >= math.sqrt(kn * b * w / m)


def test_kn_from_the_blocks_youngs_modulus():
    """k_n = E / L: a block's L is its height; a free voussoir's the chord between its joints' middles,
    2 Rp sin(half the voussoir's angle) for the equal voussoirs of a round arch."""
    import numpy as np

    from specimens import PointedArch

    st = Settings(contact_law="compliant", youngs=2e9)
    assert normal_stiffness(st, single_block(0.2, 0.4)) == pytest.approx(2e9 / 0.4)
    arch = PointedArch(e=0.0, t=0.05, Rp=0.3, width=0.1)
    m = as_model(arch, config="free", n_voussoirs=9)
    L = 2 * 0.3 * np.sin(np.pi / (2 * 19))  # nine voussoirs a side and the crown: 19 equal ones over a half circle
    assert normal_stiffness(st, m) == pytest.approx(2e9 / L, rel=1e-6)
    assert normal_stiffness(Settings(contact_law="compliant", kn=3e8), m) == 3e8


def test_omega_r_of_the_catalogue_is_of_the_studys_order():
    """docs/physics/modes.md#4: reading k_n per unit area, the free blocks of Sh06-Sd015 give 401 rad/s
    against the table's 383."""
    from specimens.catalogue import STUDY_JOINTS

    kn, w_r, _ = STUDY_JOINTS["Sh06-Sd015"]
    assert rotational_impact_frequency(as_model("Sh06-Sd015", config="free"), kn) == pytest.approx(w_r, rel=0.06)


def test_a_damping_far_above_critical_is_refused_before_any_simulation():
    """beta_R given as seconds is checked as the damping ratio it makes at omega_r (the ratio's own bound)."""
    from dem.core.contact import rayleigh_beta, rotational_impact_frequency
    from dem.core.model import from_assembly
    from dem.core.settings import MAX_DAMPING_XI, Settings
    from foundation.errors import ArchdemInputError
    from specimens.blocks import discretise
    from specimens.catalogue import get_specimen

    model = from_assembly(discretise(get_specimen("Sh06-Sd015").arch))
    w = rotational_impact_frequency(model, 1e9)
    ok = Settings(contact_law="compliant", kn=1e9, damping_beta=0.99 * 2 * MAX_DAMPING_XI / w)
    assert rayleigh_beta(ok, model) == ok.damping_beta
    with pytest.raises(ArchdemInputError, match="damping ratio xi"):
        rayleigh_beta(Settings(contact_law="compliant", kn=1e9, damping_beta=1e6), model)
