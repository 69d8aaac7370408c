"""``archdem animate``: gif of a shake run and of a tilt run; mp4 refused without ffmpeg."""
import shutil

import numpy as np
import pytest

from analytic.motions.inputs import SinePulse
from dem.core.model import single_block
from dem.core.settings import Settings
from dem.experiments.shake.animation import animate, read_run
from dem.experiments.shake.file import save_shake
from dem.experiments.shake.run import ShakeProtocol, shake
from specimens.constants import G
from foundation.errors import ArchdemInputError


@pytest.fixture(scope="module")
def shake_file(tmp_path_factory):
    res = shake(single_block(0.1, 0.4), SinePulse(0.4 * G, 3.0), Settings(planar=True), ShakeProtocol(tail=0.2))
    return save_shake(res, tmp_path_factory.mktemp("anim") / "run.h5"), res


@pytest.mark.slow
def test_gif_of_shake_run(shake_file, tmp_path):
    from PIL import Image

    path, res = shake_file
    out = animate(path, tmp_path / "a.gif", max_frames=12)
    im = Image.open(out)
    # one frame per selected record (12 evenly spaced of the run's records)
    assert im.n_frames == min(12, len(res.sim.history.t))
    run = read_run(path)
    # the trace underneath is the input in g: its peak is the pulse amplitude
    assert np.abs(run["input"]).max() == pytest.approx(0.4, rel=1e-3)
    with pytest.raises(ArchdemInputError):
        animate(path, out)  # never overwritten


@pytest.mark.slow
def test_gif_of_tilt_run(tmp_path):
    from dem.experiments.tilt.file import save_result
    from dem.experiments.tilt.run import TiltProtocol, tilt

    r = tilt(single_block(0.1, 0.4), Settings(mu_joint=10, mu_base=10, planar=True),
             TiltProtocol(kind="ramp", rate=0.5, lam_max=1.0))
    p = save_result(r, tmp_path / "tilt.h5")
    run = read_run(p)
    # the tilt trace is lambda = -g_x / g_y, rising at the ramp rate
    assert run["input"][-1] == pytest.approx(0.5 * run["input_t"][-1], rel=1e-6)
    assert animate(p, tmp_path / "t.gif", max_frames=6).stat().st_size > 0


def test_bad_requests(shake_file, tmp_path):
    path, _ = shake_file
    with pytest.raises(ArchdemInputError, match="gif or .mp4"):
        animate(path, tmp_path / "a.avi")
    if shutil.which("ffmpeg") is None:
        with pytest.raises(ArchdemInputError, match="ffmpeg"):
            animate(path, tmp_path / "a.mp4")
    bad = tmp_path / "x.h5"
    bad.write_text("not hdf5")
    with pytest.raises(ArchdemInputError, match="not an HDF5"):
        animate(bad, tmp_path / "b.gif")
