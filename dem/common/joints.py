"""The joints' named values, resolved in one place for the commands, the campaign and Python users.

Two settings of a joint have names besides numbers: its **contact fraction** (the central fraction of
its depth that touches, :func:`specimens.blocks.discretise`'s ``contact``), a number in (0, 1] or
``"calibrated"`` (the edge loss fitted to the laboratory tilt tests, :mod:`analytic.limit.calibration`);
and its **joint law** (the :class:`~dem.core.settings.Settings` fields of the contact law), rigid
(``{}``), the compliant law's fields, or ``"table-5.1"`` (the reference study's joints of a
catalogue specimen, :func:`dem.core.contact.study_joints`).
"""
from __future__ import annotations

from collections.abc import Iterable

from analytic.limit.calibration import load_calibration
from dem.core.contact import study_joints
from dem.core.settings import Settings
from specimens.blocks import check_contact
from foundation.errors import ArchdemInputError
from foundation.fields import default_of
from specimens.geometry import PointedArch
from specimens.imperfection import Imperfection

#: The contact fraction fitted to the laboratory tilt tests (per arch: a fitted edge loss).
CALIBRATED = "calibrated"
#: The joint law of the reference study's Table 5.1 (per catalogue specimen).
STUDY_JOINTS = "table-5.1"
#: The named joint laws.
JOINT_SETS = (STUDY_JOINTS,)


def contact_fraction(value: float | str | None, arch: PointedArch) -> float:
    """The contact fraction of ``arch``'s joints for ``value``: a fraction in (0, 1], ``"calibrated"``,
    or None (the full joint, 1)."""
    if value is None:
        return 1.0
    if value == CALIBRATED:
        return load_calibration().contact(arch)
    return check_contact(value)


def joint_law(value: dict | str | None, specimen_id: str | None = None) -> dict:
    """The contact-law fields of :class:`~dem.core.settings.Settings` for ``value``: None or {} (rigid:
    {}), ``"table-5.1"`` (the joints of catalogue specimen ``specimen_id``) or the fields themselves,
    checked by ``Settings``."""
    if not value:
        return {}
    if value == STUDY_JOINTS:
        return study_joints(specimen_id)
    law = dict(value)
    Settings(**law)  # the law's own checks and messages
    return law


def joint_law_settings(law: str | None = None, kn: float | None = None, youngs: float | None = None,
                       damping_beta: float | None = None, damping_xi: float | None = None, joints: str | None = None,
                       specimen_id: str | None = None, engines: Iterable[str | None] = ()) -> dict:
    """The contact-law fields of :class:`~dem.core.settings.Settings` ({} = rigid) of a law given by its
    parts, as the commands take them: ``law`` (None: compliant if ``kn`` [Pa/m], ``youngs`` [Pa] or a
    damping (``damping_beta`` [s], ``damping_xi``) is given, else the default law), or ``joints="table-5.1"``
    alone (the joints of catalogue specimen ``specimen_id``). Compliant joints on an engine of ``engines``
    that is MuJoCo need a damping. The law's checks and messages are ``Settings``'."""
    given = {k: v for k, v in (("kn", kn), ("youngs", youngs), ("damping_beta", damping_beta),
                                ("damping_xi", damping_xi)) if v is not None}
    if joints == STUDY_JOINTS:
        if given or law == "rigid":
            raise ArchdemInputError(f"--joints {STUDY_JOINTS} sets the joints: give it without --contact-law rigid, "
                                    "--kn or --damping-*")
        out = joint_law(STUDY_JOINTS, specimen_id)
    else:
        if law is None:
            law = "compliant" if given else default_of(Settings, "contact_law")
        out = {"contact_law": law, **given}
        Settings(**out)  # the law's own checks and messages
        out = {} if law == "rigid" else out
    if out and "mujoco" in tuple(engines) and not (out.get("damping_beta") or out.get("damping_xi")):
        raise ArchdemInputError("compliant joints on MuJoCo (--engine mujoco, the shakes' default) need --damping-beta or "
                                "--damping-xi: undamped, the blocks keep bouncing on their springs and the joints slip "
                                "(docs/engines.md#10-compliant-joints)")
    return out


def joint_law_text(value: dict | str | None) -> str:
    """The joint law of ``value`` in words, for summaries."""
    if not value:
        return "Rigid joints."
    if value == STUDY_JOINTS:
        return "Compliant joints: each specimen's k_n and beta_R of the study's Table 5.1."
    j = value
    damping = (f"beta_R {j['damping_beta']:g} s" if j.get("damping_beta") else
               f"xi {j['damping_xi']:g} at omega_r" if j.get("damping_xi") else "no damping")
    stiffness = f"k_n {j['kn']:.3g} Pa/m" if j.get("kn") else f"k_n = E / block length, E {j['youngs']:.3g} Pa"
    return f"Compliant joints: {stiffness}, {damping}."


def ensemble_imperfection(value: float | str | None, arch: PointedArch, scatter: float | None = None) -> Imperfection:
    """The imperfect fit of a tilt ensemble: the mean edge loss that leaves the contact fraction of
    ``value``, and the scatter of the edge losses ``scatter`` [m] (for ``"calibrated"``, by default the
    calibrated scatter)."""
    if scatter is None and value == CALIBRATED:
        scatter = load_calibration().edge_loss_sd
    if scatter is None:
        raise ArchdemInputError("a tilt ensemble needs the scatter of the joints' edge losses (--scatter MM), or the "
                                "calibrated contact (--contact calibrated: the calibrated scatter)")
    return Imperfection.from_contact(arch, contact_fraction(value, arch), scatter)
