"""The main job: the virtual test campaign on the specimen catalogue.

A campaign is a sequence of steps; each writes its files into ``OUT/<step>/`` (built in a
temporary directory and renamed when complete, so an interrupted step leaves nothing
half-written) and is recorded in ``OUT/campaign.json``. Running the campaign again on
the same directory resumes: finished steps are kept, not recomputed.
"""
from __future__ import annotations

import json
import shutil
import time
from pathlib import Path
from typing import Callable

from dem.campaign.report import build_report
from dem.campaign.step_analytic import step_analytic
from dem.campaign.step_catalogue import step_catalogue
from dem.common.campaign import CampaignContext, write_json_atomic
from dem.core.provenance import provenance
from dem.experiments.registry import steps as experiment_steps
from foundation.errors import ArchdemInputError
from foundation.io import exclusive

StepFunc = Callable[[CampaignContext, Path], dict]

# the campaign's own steps, first: what every experiment's table stands beside
_OWN = [("catalogue", step_catalogue, "specimen catalogue, drawings and meshes"),
        ("analytic", step_analytic, "limit analysis of every specimen")]

# name -> (function, description), in the order the campaign runs them: its own, then the experiments'
# steps by rank (dem.experiments.registry)
STEPS: dict[str, tuple[StepFunc, str]] = {
    **{name: (func, desc) for name, func, desc in _OWN},
    **{s.name: (s.load(), s.description) for s in experiment_steps()},
}
#: Steps run only when asked for (``--steps``, ``archdem campaign --piers``, ``--fragility`` or ``--drawing``).
OPTIONAL_STEPS = tuple(s.name for s in experiment_steps() if s.optional)


def all_steps() -> dict[str, tuple[StepFunc, str]]:
    """Every campaign step in order."""
    return STEPS


def default_steps() -> list[str]:
    """The steps a campaign runs when none are named."""
    return [s for s in STEPS if s not in OPTIONAL_STEPS]


def run_campaign(ctx: CampaignContext, steps: list[str] | None = None) -> dict:
    """Run (or resume) the campaign; return the manifest. One process at a time per folder: a
    second one is refused (``OUT/.archdem.lock``, removed when the campaign ends)."""
    ctx.out.mkdir(parents=True, exist_ok=True)
    with exclusive(ctx.out / LOCK_FILE, f"the campaign folder {ctx.out}", remove=True):
        return _run_campaign(ctx, steps)


#: The lock file of a campaign folder (held while a campaign writes into it).
LOCK_FILE = ".archdem.lock"


def _complete(out: Path, name: str, outputs: dict) -> bool:
    """A finished step's folder holds every table and figure its record lists."""
    files = [t["csv"] for t in outputs.get("tables", [])] + [f["path"] for f in outputs.get("figures", [])]
    return (out / name).is_dir() and all((out / f).is_file() for f in files)


def _run_campaign(ctx: CampaignContext, steps: list[str] | None) -> dict:
    out = ctx.out
    manifest_path = out / "campaign.json"
    manifest = json.loads(manifest_path.read_text()) if manifest_path.exists() else {}
    params = {"specimens": [s.id for s in ctx.specimens], "config": ctx.config, "engine": ctx.engine,
              "dynamics_engine": ctx.dynamics_engine, "quick": ctx.quick,
              **({} if ctx.contact == 1.0 else {"contact": ctx.contact}), **({"joints": ctx.joints} if ctx.joints else {})}
    if manifest and manifest.get("parameters") != params:
        raise ArchdemInputError(
            f"{out} holds a campaign with other parameters ({manifest.get('parameters')}); choose another --out"
        )

    manifest.setdefault("parameters", params)
    manifest.setdefault("steps", {})
    manifest["provenance"] = provenance()
    # the campaign's parameters before its first step: a campaign stopped in it resumes as itself
    write_json_atomic(manifest_path, manifest)
    for name in steps or default_steps():
        func, desc = STEPS[name]
        if name in manifest["steps"]:
            if _complete(out, name, manifest["steps"][name]["outputs"]):
                ctx.log(f"[{name}] already done ({desc}); kept")
                ctx.results[name] = manifest["steps"][name]["outputs"]
                continue
            ctx.log(f"[{name}] recorded as done but its files are incomplete (an interrupted or older run); run again")
        ctx.log(f"[{name}] {desc} ...")
        tmp = out / f".{name}.part"
        if tmp.exists():
            shutil.rmtree(tmp)
        tmp.mkdir()
        t0 = time.perf_counter()
        try:
            outputs = func(ctx, tmp)
        except BaseException:  # Ctrl-C, SIGTERM, an error: no half-written step is left (its studies are kept)
            shutil.rmtree(tmp, ignore_errors=True)
            raise
        wall = time.perf_counter() - t0
        final = out / name
        if final.exists():
            shutil.rmtree(final)
        tmp.rename(final)
        ctx.results[name] = outputs
        manifest["steps"][name] = {"outputs": outputs, "wall_s": wall}
        write_json_atomic(manifest_path, manifest)
        ctx.log(f"[{name}] done in {wall:.1f} s")

    # the report's own entry is left out, so a resumed campaign writes the same campaign.h5
    rep = build_report(out, {k: v for k, v in manifest.items() if k != "report"}, {k: v[1] for k, v in STEPS.items()})
    manifest["report"] = rep["report"]
    write_json_atomic(manifest_path, manifest)
    return manifest
