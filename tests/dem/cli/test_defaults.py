"""The CLI declares no physical or numerical default of its own: every such default of a
sub-command, and the value its help text shows, is the library's (a dataclass field, a function
parameter or a module constant). A literal re-declared in ``dem/cli`` that drifts from the
library fails here, and so does a new option default that is neither listed below with its
library source nor among the CLI-only options."""
import argparse
import functools

import pytest

from dem.cli import build_parser
from dem.common.options import default_of


def _lib():
    """Library source of every physical / numerical default, by (sub-command, dest)."""
    from analytic.codes.assessment import assess
    from analytic.codes.frp import Strips
    from analytic.codes.kinematic import Height
    from analytic.compliant.modes import POISSON, modes
    from analytic.limit.calibration import CALIBRATION_FILE
    from analytic.limit.summary import analyse
    from analytic.motions.spectra import ntc2018
    from analytic.rocking.domain import failure_domain
    from dem.common.campaign import CampaignContext
    from dem.core.settings import DYNAMICS_ENGINE, Settings
    from dem.experiments.compare_engines.run import compare
    from dem.experiments.compare_engines.shake import study_cases
    from dem.experiments.fragility.run import DEFAULT_FRICTION_COV
    from dem.experiments.friction_map.run import catalogue_map
    from dem.experiments.shake.animation import animate
    from dem.experiments.shake.domain import dem_failure_domain
    from dem.experiments.shake.run import ShakeProtocol
    from dem.experiments.shake.thresholds import threshold
    from dem.experiments.tilt.case import MAP_TILT_TOL
    from dem.experiments.tilt.run import TiltProtocol
    from specimens.blocks import discretise

    s, sp, tp = Settings(), ShakeProtocol(), TiltProtocol()
    sim = {"config": default_of(discretise, "config"), "mu_joint": s.mu_joint, "mu_base": s.mu_base,
           "engine": s.engine}
    return {
        "mesh": {"config": default_of(discretise, "config"), "shape": default_of(discretise, "shape")},
        "draw": {"config": default_of(discretise, "config"), "shape": default_of(discretise, "shape")},
        "analytic": {"config": default_of(discretise, "config"),
                     "effective_thickness": default_of(analyse, "effective_thickness"),
                     "min_spacing": default_of(analyse, "min_spacing")},
        "campaign": {"config": default_of(CampaignContext, "config"), "engine": s.engine,
                     "dynamics_engine": default_of(CampaignContext, "dynamics_engine"),
                     "contact": default_of(CampaignContext, "contact")},
        "calibrate": {"out": str(CALIBRATION_FILE)},
        "assess": {"soil": default_of(ntc2018, "soil"), "topography": default_of(ntc2018, "topography"),
                   "damping": default_of(ntc2018, "damping"), "FC": default_of(assess, "FC"),
                   "q": default_of(assess, "q"), "limit_state": default_of(assess, "limit_state"),
                   "building_damping": default_of(Height, "damping1"), "engine": DYNAMICS_ENGINE,
                   **{f"frp_{k}": default_of(Strips, k) for k in ("fibre", "exposure", "application")}},
        "tilt": {**sim, "protocol": tp.kind, "start": tp.start},
        "map": {"config": default_of(catalogue_map, "config"), "mu": default_of(catalogue_map, "mus"),
                "mu_base": default_of(catalogue_map, "mu_base"), "refine": default_of(catalogue_map, "refine"),
                "tol": MAP_TILT_TOL, "engine": s.engine, "contact": default_of(catalogue_map, "contact")},
        "domain": {"amax": default_of(failure_domain, "a_max_ratio"), "scan": default_of(failure_domain, "n_scan"),
                   "tol": default_of(failure_domain, "tol"), "config": default_of(dem_failure_domain, "config")},
        "shake": {**sim, "engine": DYNAMICS_ENGINE, "tail": sp.tail, "load": sp.load},
        "threshold": {**sim, "engine": DYNAMICS_ENGINE, "tail": sp.tail, "load": sp.load,
                      "scan_ratio": default_of(threshold, "scan_ratio"), "tol": default_of(threshold, "tol")},
        "animate": {"fps": default_of(animate, "fps"), "frames": default_of(animate, "max_frames")},
        "fragility": {"config": default_of(discretise, "config"), "mu_joint": s.mu_joint, "mu_base": s.mu_base,
                      "engine": DYNAMICS_ENGINE, "friction_cov": DEFAULT_FRICTION_COV},
        "modes": {"config": default_of(discretise, "config"), "springs": default_of(modes, "springs"),
                  "poisson": POISSON},
        "compare-engines": {"config": default_of(compare, "config"), "engines": ",".join(default_of(compare, "engines"))},
        "compare-shake": {"config": default_of(study_cases, "config"),
                          **{dest: ",".join(v if isinstance(v, str) else f"{v:g}" for v in default_of(study_cases, k))
                             for dest, k in (("specimens", "ids"), ("engines", "engines"), ("freq", "freqs"),
                                             ("steps", "steps"), ("friction", "frictions"))}},
    }


# Options whose default belongs to the CLI (choices of what to run or show, output places, processes).
CLI_ONLY = {
    ("mesh", "format"), ("record", "format"),
    ("campaign", "specimens"), ("map", "specimens"), ("compare-engines", "specimens"),
    ("campaign", "out"), ("tilt", "out"), ("shake", "out"),
    ("domain", "layout"), ("domain", "input"), ("domain", "restitution"), ("domain", "engine"),
    ("rock", "layout"), ("rock", "input"), ("rock", "restitution"),
    ("compare-engines", "friction"), ("compare-engines", "workers"),
    ("assess", "frp_face"), ("fragility", "seed"), ("modes", "count"),
}

# A minimal command line of every sub-command.
ARGV = {
    "specimens": [], "mesh": ["Sh02-Sd015", "--out", "o"], "draw": ["Sh02-Sd015", "--out", "o.png"],
    "analytic": ["Sh02-Sd015"], "assess": ["Sh02-Sd015", "--spectrum", "ec8"], "calibrate": [], "campaign": [], "tilt": ["Sh02-Sd015"], "map": [], "record": ["f.AT2"],
    "domain": ["Sh02-Sd015"], "rock": ["Sh02-Sd015"], "shake": ["Sh02-Sd015"],
    "threshold": ["Sh02-Sd015", "--sine", "4"], "fragility": ["Sh02-Sd015", "--realizations", "1"],
    "modes": ["Sh02-Sd015", "--kn", "1e8"],
    "animate": ["run.h5", "--out", "a.gif"], "compare-engines": [], "compare-shake": [], "settle": ["Sh02-Sd015"],
}


def _subparsers() -> dict[str, argparse.ArgumentParser]:
    p = build_parser()
    return next(a for a in p._actions if isinstance(a, argparse._SubParsersAction)).choices


def _help(cmd: str, dest: str) -> str:
    return next(a.help for a in _subparsers()[cmd]._actions if a.dest == dest)


def test_every_sub_command_has_a_minimal_command_line():
    assert set(ARGV) == set(_subparsers())


@pytest.mark.parametrize("cmd", sorted(ARGV))
def test_parsed_defaults_are_the_librarys(cmd):
    args = build_parser().parse_args([cmd] + ARGV[cmd])
    for dest, value in _lib().get(cmd, {}).items():
        got = getattr(args, dest)
        assert got == value and type(got) is type(value), f"{cmd} --{dest}: {got!r}, library {value!r}"


@pytest.mark.parametrize("cmd", sorted(ARGV))
def test_no_default_without_a_library_source(cmd):
    # a new option default: give it its library source above, or list it as CLI-only
    lib = _lib().get(cmd, {})
    own = {a.dest for a in _subparsers()[cmd]._actions
           if a.dest != "help" and a.default not in (None, False, argparse.SUPPRESS)}
    assert own - set(lib) - {d for c, d in CLI_ONLY if c == cmd} == set()


def test_help_texts_show_the_library_values():
    from analytic.rocking.domain import failure_domain
    from dem.core.settings import DYNAMICS_DT, DYNAMICS_ENGINE, Settings
    from dem.experiments.compare_engines.run import FRICTIONS
    from dem.experiments.shake.animation import animate
    from dem.experiments.shake.domain import dem_failure_domain
    from dem.experiments.shake.run import ShakeProtocol
    from dem.experiments.shake.step_shake import SHAKE_FREQS
    from dem.experiments.tilt.run import TiltProtocol
    from specimens.blocks import DEFAULT_DENSITY, DEFAULT_VOUSSOIRS, discretise
    from specimens.catalogue import SPECIMEN_WIDTH
    from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT

    s, tp = Settings(), TiltProtocol()
    assert DEFAULT_VOUSSOIRS == default_of(discretise, "n_voussoirs")
    assert DEFAULT_DENSITY == default_of(discretise, "density")
    for cmd in ("tilt", "shake", "threshold", "analytic", "domain", "rock", "mesh", "draw"):
        assert f"else {SPECIMEN_WIDTH:g})" in _help(cmd, "width")
        assert f"(default {DEFAULT_VOUSSOIRS})" in _help(cmd, "voussoirs")
        assert f"(default {DEFAULT_DENSITY:g})" in _help(cmd, "density")
        assert f"(default {default_of(discretise, 'contact'):g}:" in _help(cmd, "contact")
    for cmd in ("tilt", "shake", "threshold"):
        assert f"(default {s.mu_joint:g})" in _help(cmd, "mu_joint")
        assert f"(default {s.mu_base:g})" in _help(cmd, "mu_base")
        assert (f"(default {s.dt:g})" if cmd == "tilt" else
                f"(default {DYNAMICS_DT:g} on {DYNAMICS_ENGINE}, {s.dt:g} on the other engines)") in _help(cmd, "dt")
    for cmd in ("shake", "threshold"):
        assert f"(default {ShakeProtocol().tail:g})" in _help(cmd, "tail")
    for cmd in ("analytic", "domain"):  # None: the library's reference friction
        assert f"(default {REFERENCE_MU_JOINT:g})" in _help(cmd, "mu_joint")
        assert f"(default {REFERENCE_MU_BASE:g})" in _help(cmd, "mu_base")
    assert f"full {tp.hold_time:g} s" in _help("tilt", "full_hold")
    assert f"rest {tp.rest_after:g} s into" in _help("tilt", "full_hold")
    assert f"(default {s.engine})" in _help("tilt", "engine")
    assert f"--engine dem {default_of(dem_failure_domain, 'a_max_ratio'):g})" in _help("domain", "amax")
    assert f"(default {default_of(failure_domain, 'a_max_ratio'):g};" in _help("domain", "amax")
    assert f"--engine dem {','.join(f'{f:g}' for f in SHAKE_FREQS)})" in _help("domain", "freq")
    assert f"(default {default_of(animate, 'max_frames')})" in _help("animate", "frames")
    assert f"{FRICTIONS['reference'][0]:g}/{FRICTIONS['reference'][1]:g}" in _help("compare-engines", "friction")
    assert f"(default {s.dt:g})" in _help("compare-engines", "dt")


def test_animate_frames_default_is_the_clis():
    # the CLI's 200 frames became the library default (it read 300 while the CLI passed 200)
    from dem.experiments.shake.animation import animate

    assert default_of(animate, "max_frames") == 200


def test_dem_domain_uses_the_dem_defaults(monkeypatch, capsys):
    # `archdem domain --engine dem`: the analytic --amax default means the DEM's own a_max_ratio,
    # the frequencies default to the campaign's shake frequencies
    from dem.core.settings import DYNAMICS_ENGINE
    import dem.experiments.shake.domain_spec as dd
    from dem.cli import main
    from dem.experiments.shake.domain import dem_failure_domain
    from dem.experiments.shake.step_shake import SHAKE_FREQS
    from specimens.constants import REFERENCE_MU_BASE, REFERENCE_MU_JOINT

    seen = {}

    @functools.wraps(dem_failure_domain)  # the real signature: the CLI reads its defaults from it
    def fake(label, arch, freqs, config, mu_joint, mu_base, **kw):
        seen.update(freqs=freqs, config=config, mu_joint=mu_joint, mu_base=mu_base, **kw)
        return {"config": config, "mu_joint": REFERENCE_MU_JOINT, "mu_base": REFERENCE_MU_BASE, "lambda": 0.3,
                "thresholds": [], "a_range_g": [0.3, 1.8], "physics_engine": "pybullet", "dt": 5e-4}

    monkeypatch.setattr(dd, "dem_failure_domain", fake)
    assert main(["domain", "Sh02-Sd015", "--engine", "dem"]) == 0
    assert seen["freqs"] == list(SHAKE_FREQS)
    assert seen["a_max_ratio"] == default_of(dem_failure_domain, "a_max_ratio")
    assert seen["config"] == default_of(dem_failure_domain, "config")
    assert seen["mu_joint"] is None and seen["mu_base"] is None  # the library's reference friction
    assert seen["engine"] == DYNAMICS_ENGINE and seen["dt"] is None  # 'dem': the shakes' engine at its step
    assert main(["domain", "Sh02-Sd020", "--engine", "pybullet", "--dt", "2.5e-4"]) == 0
    assert (seen["engine"], seen["dt"]) == ("pybullet", 2.5e-4)
    assert main(["domain", "Sh02-Sd015", "--engine", "dem", "--amax", "3", "--freq", "2,5"]) == 0
    assert seen["a_max_ratio"] == 3.0 and seen["freqs"] == [2.0, 5.0]
    capsys.readouterr()


def test_default_of():
    from dataclasses import dataclass, field

    @dataclass
    class D:
        a: int
        b: float = 0.5
        c: list = field(default_factory=lambda: [1])

    def f(x, y=3, *, z="k"):
        return x

    assert default_of(D, "b") == 0.5 and default_of(D, "c") == [1]
    assert default_of(f, "y") == 3 and default_of(f, "z") == "k"
    for obj, name in ((D, "a"), (D, "nope"), (f, "x"), (f, "nope")):
        with pytest.raises(LookupError):
            default_of(obj, name)
