"""The rocking linkage a command asks for, checked once: the options ``archdem domain`` and ``archdem rock``
share (:class:`LinkageOptions`: the linkage, its hinge layout, its input, the restitution) and the
mechanism they build of an :class:`~dem.common.request.ArchRequest`; one time history of it under a pulse,
a sine or a record (:class:`RockSpec` -> :func:`rock` -> :class:`RockResult`, ``archdem rock``)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace
from typing import Any

from analytic.motions.records import read_record
from analytic.rocking.domain import make_input
from dem.common.joints import contact_fraction
from dem.common.request import ArchRequest
from foundation.errors import ArchdemInputError
from specimens.blocks import DEFAULT_DENSITY, discretise
from specimens.catalogue import SPECIMEN_WIDTH
from specimens.constants import G


def option(default: Any, help: str, unit: str = "", **meta: Any) -> Any:
    """A field that is an option (:func:`dem.experiments.contract.add_spec_options`): its help, unit and
    argparse's ``choices``, ``metavar`` or ``shown`` (the default the help shows; None: none)."""
    return field(default=default, metadata={"help": help, "unit": unit, **meta})


def unused(spec: Any, name: str, used: bool, why: str) -> None:
    """Option ``name`` typed (``spec.given``) where it does nothing, refused in one line (``why``: what it
    belongs to)."""
    if not used and name in spec.given:
        raise ArchdemInputError(f"--{name.replace('_', '-')} does nothing here: {why}")


@dataclass(frozen=True)
class LinkageOptions:
    """The linkage of ``archdem domain`` and ``archdem rock``: ``model`` (four-bar by default, two-bar or a
    block), the four-bar's hinge ``layout``, the ground ``input`` and the energy ``restitution`` (``auto``:
    the momentum balance). ``request``: the structure; ``given``: the options set by hand (one that does
    nothing here is refused when given, even at its default)."""

    model: str | None = option(None, "linkage", choices=("four-bar", "two-bar", "block"), shown="four-bar")
    layout: str = option("minimised", "four-bar hinge layout: minimised (continuous ring) | discrete (minimum "
                         "mechanism of the voussoirs, piers included; the only one on piers) | oppenheim | "
                         "'b1,b2,b3,b4' (polar angles about O, rad)", shown=None)
    input: str = option("sine", "phased one-cycle sine (starts at the onset), plain one-cycle sine, pulse A or B",
                        choices=("sine", "sine0", "A", "B"), shown=None)
    restitution: str = option("auto", "'auto' (momentum balance) or an energy restitution in [0, 1]", shown=None)
    request: ArchRequest = field(default_factory=ArchRequest)
    given: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        # argparse checks the choices on the command line; a script meets the same rule here
        for f in fields(LinkageOptions):
            v, choices = getattr(self, f.name), f.metadata.get("choices")
            if choices and v is not None and v not in choices:
                raise ArchdemInputError(f"--{f.name} must be one of {', '.join(choices)}, got {v!r}")

    @property
    def pulses(self) -> bool:
        """The input is pulse A or B (a duration, not a frequency)."""
        return self.input in ("A", "B")

    @property
    def energy_restitution(self) -> float | None:
        """``restitution`` as a number in [0, 1], None for ``auto`` (momentum balance)."""
        if self.restitution == "auto":
            return None
        try:
            v = float(self.restitution)
        except ValueError:
            raise ArchdemInputError(f"--restitution must be 'auto' or a number in [0, 1], got {self.restitution!r}") from None
        if not 0 <= v <= 1:
            raise ArchdemInputError(f"--restitution must be in [0, 1], got {v:g}")
        return v

    def mechanism(self) -> tuple[str, Any]:
        """``(label, mechanism)`` opened by a positive ground acceleration."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.rocking import linkage

        req = self.request
        unused(self, "layout", req.block is None and self.model in (None, "four-bar"),
               "it places the hinges of the four-bar (--model four-bar)")
        density = DEFAULT_DENSITY if req.density is None else req.density
        if req.block is not None:
            # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
            from analytic.rocking.rocking_block import RockingBlock

            if self.model not in (None, "block"):
                raise ArchdemInputError("--block goes with --model block")
            b, h = req.block
            width = req.width if req.width is not None else SPECIMEN_WIDTH
            return f"block b={b:g} h={h:g}", RockingBlock(b, h, -1, density, width)
        label, arch = req.structure()
        model = self.model or "four-bar"
        if model == "block":
            raise ArchdemInputError("--model block needs --block B H")
        if req.piers is not None or self.layout == "discrete":
            return label, self._discrete_four_bar(arch, model, density)
        contact = contact_fraction(req.contact, arch)
        if model == "two-bar":
            if contact != 1.0:
                raise ArchdemInputError("--contact is not modelled by the two-bar linkage; use the four-bar")
            return label, linkage.arch_two_bar(arch, density, direction=1)
        lay = self.layout
        if lay == "minimised":
            return label, linkage.minimised_four_bar(arch, density, direction=1, contact=contact)
        layout = linkage.oppenheim_hinges(arch) if lay == "oppenheim" else linkage.parse_hinge_angles(arch, lay)
        layout = tuple(replace(h, contact=contact) for h in layout)
        fb = linkage.arch_four_bar(arch, layout, density, direction=1, name=f"four-bar ({lay if ',' not in lay else 'user'})")
        if not fb.admissible:
            raise ArchdemInputError(f"the {lay} hinge layout is not an admissible mechanism for this arch")
        return label, fb

    def _discrete_four_bar(self, arch: Any, model: str, density: float) -> Any:
        """The four-bar of the discrete minimum mechanism (the only linkage of an arch on piers)."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.rocking.linkage import mechanism_four_bar

        if model != "four-bar":
            raise ArchdemInputError("an arch on piers rocks as the four-bar of its discrete mechanism; use --model four-bar")
        if self.layout not in ("minimised", "discrete"):
            raise ArchdemInputError("on piers the four-bar's hinges are those of the discrete mechanism; use --layout discrete")
        kw = self.request.discretise_kwargs(arch)
        kw["density"] = density
        return mechanism_four_bar(discretise(arch, **kw), direction=1)


@dataclass(frozen=True)
class RockSpec(LinkageOptions):
    """One time history of the linkage: a sine of ``freq`` [Hz] or pulse A/B of ``duration`` [s] at
    ``amplitude`` [g], or a recorded accelerogram ``record`` (a file) times ``scale``; checked in one line
    per refusal, naming the option typed."""

    freq: float | None = option(None, "sine frequency", "Hz", shown=None)
    duration: float | None = option(None, "pulse duration t_i [s] (pulses A/B)", shown=None)
    amplitude: float | None = option(None, "amplitude", "g", shown=None)
    record: str | None = option(None, "recorded accelerogram (AT2, SMC, ESM, CSV) instead of --input", metavar="FILE",
                                shown=None)
    scale: float | None = option(None, "factor applied to the record", shown=None)

    def __post_init__(self) -> None:
        super().__post_init__()
        self.energy_restitution  # noqa: B018 (its refusal first, as the command line reads it)
        rec = self.record is not None
        unused(self, "scale", rec, "it scales a --record")
        unused(self, "amplitude", not rec, "a --record is scaled by --scale")
        unused(self, "input", not rec, "a --record is the input")
        unused(self, "freq", not rec and not self.pulses, "it is a sine's (pulses A/B take --duration)")
        unused(self, "duration", not rec and self.pulses, "it is the length of pulses A/B (a sine takes --freq)")
        if rec:
            if self.scale is None or not (self.scale > 0 and math.isfinite(self.scale)):
                raise ArchdemInputError("--scale (a positive factor) is needed with --record")
            return
        if self.amplitude is None or not (math.isfinite(self.amplitude) and 0 < self.amplitude <= 100):
            raise ArchdemInputError(f"--amplitude (in g) must be a positive number up to 100, got {self.amplitude}")
        x = self.x
        if x is None:
            raise ArchdemInputError("--duration (s) is needed for pulses A/B" if self.pulses else "--freq (Hz) is needed for sines")
        if not (math.isfinite(x) and 0.01 <= x <= 100):
            raise ArchdemInputError(f"{'--duration [s]' if self.pulses else '--freq [Hz]'} must be in [0.01, 100], got {x:g}")

    @property
    def x(self) -> float | None:
        """The input's duration [s] (pulses) or frequency [Hz] (sines)."""
        return self.duration if self.pulses else self.freq


@dataclass(frozen=True)
class RockResult:
    """A time history (``response``, :class:`analytic.rocking.dynamics.Response`) of ``mechanism`` (of the
    structure ``label``) under ``motion``, described as ``what``."""

    label: str
    mechanism: Any
    motion: Any
    what: str
    response: Any

    def to_json(self) -> dict:
        """What ``archdem rock --json`` prints: the linkage, the input and the response's summary."""
        return {"model": self.mechanism.summary(), "input": self.motion.describe(), **self.response.summary()}

    def lines(self) -> list[str]:
        """What ``archdem rock`` prints: the linkage, then collapse or survival, the largest rotation over
        the critical one, the impacts and the collapse time [s]."""
        m, r = self.mechanism, self.response
        return [f"{self.label}  {m.label}  lambda {m.lam:.4f}  phi_cr {m.phi_cr:.4g} rad",
                f"{'COLLAPSE' if r.collapsed else 'survival'} ({r.rule}{', ' + r.mode if r.mode else ''})  "
                f"max phi/phi_cr {r.max_ratio:.4f}  impacts {r.n_impacts}"
                + (f"  t_collapse {r.t_collapse:.4f} s" if r.t_collapse is not None else "")]

    def plot(self, path: str) -> None:
        """The rotation / phi_cr against time [s], the input's end marked, into ``path``."""
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from analytic.rocking.figures import plot_response

        plot_response(self.response, path, title=f"{self.label}: {self.what}", input_end=self.motion.duration)


def rock(spec: RockSpec) -> RockResult:
    """The time history ``spec`` asks for (:func:`analytic.rocking.dynamics.simulate`, the impacts recorded)."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from analytic.rocking.dynamics import simulate

    rest = spec.energy_restitution
    if spec.record is not None:
        motion = read_record(spec.record).scaled(spec.scale)
        label, mech = spec.mechanism()
        what = f"record {motion.name or spec.record} x {spec.scale:g}"
    else:
        label, mech = spec.mechanism()
        a = spec.amplitude * G
        if spec.input == "sine" and a < abs(mech.onset):
            raise ArchdemInputError(f"the phased sine needs amplitude >= onset lambda = {mech.lam:.4f} g")
        motion = make_input(spec.input, a, spec.x, abs(mech.onset))
        what = f"{spec.input} {spec.x:g} {'s' if spec.pulses else 'Hz'}, {spec.amplitude:g} g"
    return RockResult(label, mech, motion, what, simulate(mech, motion, restitution=rest, record=True))


__all__ = ["LinkageOptions", "RockSpec", "RockResult", "rock"]
