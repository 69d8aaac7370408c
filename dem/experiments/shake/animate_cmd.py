"""``archdem animate``: the animation of a tilt or shake run file (gif, or mp4 with ffmpeg)."""
from __future__ import annotations

import argparse

from dem.common.options import add_options, default_of
from dem.experiments.shake.animation import animate


def _run_animate(args: argparse.Namespace) -> int:
    out = animate(args.run, args.out, fps=args.fps, max_frames=args.frames)
    print(out)
    return 0


def register(sub) -> None:
    r = sub.add_parser("animate", help="animation of a tilt or shake run file (gif, or mp4 with ffmpeg)")
    r.add_argument("run", help="run file (.h5) written by `archdem tilt` or `archdem shake`")
    add_options(r, "animate")
    r.add_argument("--fps", type=int, default=default_of(animate, "fps"),
                   help=f"frames per second (default {default_of(animate, 'fps')})")
    r.add_argument("--frames", type=int, default=default_of(animate, "max_frames"),
                   help=f"most frames (default {default_of(animate, 'max_frames')})")
    r.set_defaults(func=_run_animate)
