"""The options of ``archdem fragility`` besides the structure and the settings, as one frozen spec: each
field is an option (its help, unit, metavar and aliases in its metadata, its default the library's);
the command adds them from the fields (:func:`dem.experiments.contract.add_spec_options`)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from dem.experiments.fragility.run import DEFAULT_EDGE_LOSS_SD, DEFAULT_FRICTION_COV, DEFAULT_SIZE_SD


def _opt(default: Any, help: str, unit: str = "", **meta: Any) -> Any:
    """A field that is an option: ``help`` and ``unit`` for its help text, and argparse's ``metavar``,
    ``nargs``, ``aliases`` or ``shown`` (the library default the help shows when the field's is None)."""
    return field(default=default, metadata={"help": help, "unit": unit, **meta})


@dataclass(frozen=True)
class FragilityOptions:
    """The motions (sine pulses of ``sine`` [Hz] at ``amplitudes`` [g], or the suite ``records`` scaled
    to the ``stripes`` of ``im``), ``realizations`` per stripe from ``seed``, and the perturbation
    (``edge_loss``, ``edge_loss_sd``, ``size_sd`` [mm], ``friction_cov``); each checked where it is used
    (:mod:`dem.experiments.fragility.inputs`, :func:`dem.experiments.fragility.run.make_cases`)."""

    sine: str | None = _opt(None, "one-cycle sine pulses of these frequencies", "Hz", metavar="F[,F...]")
    amplitudes: str | None = _opt(None, "sine amplitudes [g]: START:STOP:STEP or a,b,c", metavar="GRID")
    records: tuple[str, ...] | None = _opt(None, "a suite of records (.AT2, .smc, ESM, CSV)", nargs="+",
                                           metavar="FILE")
    im: str | None = _opt(None, "intensity measure of the records' stripes", metavar="pga|pgv|sa:T")
    stripes: str | None = _opt(None, "intensities of the stripes (g; m/s for pgv)", metavar="GRID")
    realizations: int | None = _opt(None, "perturbed realisations per stripe (needed; a resume takes the study's)",
                                    aliases=("--realisations",))
    seed: int = _opt(0, "seed of the realisations")
    edge_loss: float | None = _opt(None, "arch: mean edge loss of every joint", "mm", shown=0.0)
    edge_loss_sd: float | None = _opt(None, "arch: scatter of the joints' edge loss", "mm",
                                      shown=DEFAULT_EDGE_LOSS_SD * 1e3)
    size_sd: float | None = _opt(None, "block: scatter of a block's base and height", "mm", shown=DEFAULT_SIZE_SD * 1e3)
    friction_cov: float = _opt(DEFAULT_FRICTION_COV, "coefficient of variation of the friction coefficients")
    no_deterministic: bool = _opt(False, "skip the nominal structure's threshold beside each sine curve", shown=None)
