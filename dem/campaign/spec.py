"""What a campaign is asked to run, checked before its folder is made: its steps, the parameters a
campaign folder resumes with, and the time it is estimated to take, as ``archdem campaign`` says it."""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from dem.common.campaign import CampaignContext
from specimens.catalogue import select_specimens
from foundation.errors import ArchdemInputError

#: The parameters a campaign folder stores and resumes with (its ``campaign.json``).
RESUMED = ("specimens", "config", "engine", "dynamics_engine", "quick", "contact", "joints")


def campaign_steps(text: str | None, added: tuple[str, ...] = ()) -> list[str] | None:
    """The steps of ``--steps`` (comma-separated names; None: the default ones) with the optional steps
    ``added`` (``--piers``, ``--fragility``, ``--drawing``) after them; unknown names refused."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.campaign.runner import all_steps, default_steps

    steps = None
    if text is not None:
        steps = [s.strip() for s in text.split(",")]
        if not all(steps):
            raise ArchdemInputError(f"--steps: give step names separated by commas, got {text!r}")
        unknown = [s for s in steps if s not in all_steps()]
        if unknown:
            raise ArchdemInputError(f"unknown campaign step(s) {', '.join(unknown)}; steps: {', '.join(all_steps())}")
    for name in added:
        steps = (steps or default_steps()) + ([] if steps and name in steps else [name])
    return steps


def resumed(out: str | Path, values: dict[str, Any], given: frozenset[str]) -> dict[str, Any]:
    """``values`` (the :data:`RESUMED` parameters asked for, ``specimens`` as text) with those of the
    campaign in ``out`` in place of the ones not ``given`` by hand; one given with another value is
    refused in one line, before any simulation. No campaign there (or none readable): ``values``."""
    try:
        params = json.loads((Path(out) / "campaign.json").read_text()).get("parameters") or {}
    except (OSError, ValueError, AttributeError):
        return values  # no campaign there yet (or no readable one: the runner says so)
    stored = {k: params.get(k) for k in ("specimens", "config", "engine", "dynamics_engine", "quick")}
    stored["contact"] = params.get("contact", 1.0)  # a campaign from before the option had full joints
    if params.get("joints") == "table-5.1":
        stored["joints"] = "table-5.1"
    values = dict(values)
    for k, v in stored.items():
        if v is None:
            continue
        have = [s.id for s in select_specimens(values["specimens"])] if k == "specimens" else values[k]
        if k in given and have != v:
            raise ArchdemInputError(f"--{k.replace('_', '-')} {values['specimens'] if k == 'specimens' else have} is "
                                    f"not the campaign's in {out} ({','.join(v) if k == 'specimens' else v}); give it "
                                    "without it, or choose another --out")
        values[k] = ",".join(v) if k == "specimens" else v
    return values


def duration(seconds: float) -> str:
    """``seconds`` in s, min or h."""
    if seconds < 90:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"


def estimate_line(ctx: CampaignContext, steps: list[str]) -> str | None:
    """The campaign's time estimate in one line, this machine timed first (about 1 s); None when
    ``steps`` run no simulator."""
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from dem.campaign.estimate import REFERENCE_SPEED, estimate, machine_speed

    if not estimate(ctx, steps):
        return None
    speed = machine_speed(ctx.engine)
    est = estimate(ctx, steps, speed=speed)
    total = sum(e["wall_s"] for e in est.values())
    parts = "; ".join(f"{k}: {e['units']} {e['what']}" for k, e in est.items())
    return (f"{'quick' if ctx.quick else 'full'} campaign, {ctx.engine} (shakes {ctx.dynamics_engine}): {parts}; "
            f"estimated {duration(total)} of simulation at this machine's {speed:.2f} s per simulated second "
            f"(the unit costs are for a machine reading {REFERENCE_SPEED[ctx.engine]:.2f}; steps already finished "
            f"in {ctx.out} are kept)")
