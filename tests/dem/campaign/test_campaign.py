"""The campaign's up-front estimate: what each simulator step will run (no simulation here)."""
from pathlib import Path

import pytest

from dem.campaign.estimate import estimate
from dem.campaign.runner import all_steps
from dem.common.campaign import CampaignContext
from specimens.catalogue import select_specimens


@pytest.mark.parametrize("quick, units", [
    # quick: 11 tilts at the reference friction; 6 tested specimens x 3 realisations + 5 predictions;
    # 2 specimens x (4 frictions + 1 bisection); Sh02-Sd020 at 2 and 6 Hz; one record
    (True, {"tilt": 11, "lab": 6 * 3 + 5, "map": 10, "shake": 2, "record": 1}),
    # full: 11 x 2 frictions; 6 x 10 realisations + 5; 11 x (13 + 3); the six Sd = 0.15 / 0.20
    # specimens x 5 frequencies; 3 records
    (False, {"tilt": 22, "lab": 6 * 10 + 5, "map": 176, "shake": 30, "record": 3}),
])
def test_estimate_counts_the_work_of_each_step(quick, units, tmp_path):
    ctx = CampaignContext(out=Path(tmp_path), specimens=select_specimens("all"), quick=quick, workers=2)
    est = estimate(ctx, list(all_steps()))
    assert {k: v["units"] for k, v in est.items()} == units
    assert all(v["wall_s"] > 0 for v in est.values())
    one_core = estimate(CampaignContext(out=Path(tmp_path), specimens=ctx.specimens, quick=quick, workers=1),
                        ["tilt"])
    assert one_core["tilt"]["wall_s"] == pytest.approx(2 * est["tilt"]["wall_s"])


def test_estimate_only_for_requested_simulator_steps(tmp_path):
    ctx = CampaignContext(out=Path(tmp_path), specimens=select_specimens("all"), quick=True, workers=2)
    assert set(estimate(ctx, ["catalogue", "analytic", "tilt"])) == {"tilt"}


def test_estimate_scales_with_the_measured_machine_speed(tmp_path):
    """A machine twice as slow per simulated second as the reference gets twice the estimate."""
    from dem.campaign.estimate import REFERENCE_SPEED

    ctx = CampaignContext(out=Path(tmp_path), specimens=select_specimens("all"), quick=True, workers=2)
    base = estimate(ctx, list(all_steps()))
    same = estimate(ctx, list(all_steps()), speed=REFERENCE_SPEED["pybullet"])
    slow = estimate(ctx, list(all_steps()), speed=2 * REFERENCE_SPEED["pybullet"])
    for k in base:
        assert same[k]["wall_s"] == pytest.approx(base[k]["wall_s"])
        assert slow[k]["wall_s"] == pytest.approx(2 * base[k]["wall_s"])


@pytest.mark.parametrize("engine", ["pybullet", "mujoco"])
def test_machine_speed_times_the_engine_it_is_given(engine, monkeypatch):
    # a stand-in clock that advances 1 ms per step of this engine's class alone: the speed must be
    # exactly 1 ms / dt wall seconds per simulated second (steps of another engine would read 0)
    import time

    from dem.campaign.estimate import machine_speed
    from dem.core.engines import get_engine
    from dem.core.settings import Settings

    cls = type(get_engine(engine))
    real_step, clock = cls.step, [0.0]

    def step(self, n=1):
        real_step(self, n)
        clock[0] += 1e-3 * n

    monkeypatch.setattr(cls, "step", step)
    monkeypatch.setattr(time, "perf_counter", lambda: clock[0])
    s = machine_speed(engine, steps=20, repeats=3)
    assert s == pytest.approx(1e-3 / Settings(engine=engine).dt, rel=1e-12)


def test_the_record_step_finds_its_record():
    from dem.experiments.record.step_record import _record_path

    assert _record_path().is_file()


def test_a_second_writer_of_a_campaign_folder_is_refused(tmp_path, capsys):
    """Two campaigns into one folder: while another process holds the folder, a campaign there
    is refused in one line (exit 2) and writes nothing."""
    import subprocess
    import sys

    from dem.campaign.runner import LOCK_FILE
    from dem.cli import main

    out = tmp_path / "c"
    out.mkdir()
    holder = subprocess.Popen(
        [sys.executable, "-c", "import sys, time; from foundation.io import exclusive\n"
         f"with exclusive({str(out / LOCK_FILE)!r}, 'x'):\n    print('held', flush=True); time.sleep(30)"],
        stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        assert main(["campaign", "--steps", "catalogue", "--specimens", "Sh02-Sd020", "--out", str(out)]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "being written by another archdem process" in err
        assert [p.name for p in out.iterdir()] == [LOCK_FILE]
    finally:
        holder.kill()
        holder.wait()


def test_a_step_recorded_done_with_missing_files_is_run_again(tmp_path):
    from dem.campaign.runner import run_campaign

    log: list[str] = []
    ctx = CampaignContext(out=tmp_path, specimens=select_specimens("Sh02-Sd020"), log=log.append)
    run_campaign(ctx, ["catalogue"])
    table = tmp_path / "catalogue" / "catalogue.csv"
    text = table.read_text()
    table.unlink()  # as an interrupted older version could leave it
    log.clear()
    run_campaign(ctx, ["catalogue"])
    assert any("incomplete" in ln for ln in log) and not any("kept" in ln for ln in log)
    assert table.read_text() == text
    log.clear()
    run_campaign(ctx, ["catalogue"])
    assert [ln for ln in log if ln.startswith("[catalogue]")] == [
        "[catalogue] already done (specimen catalogue, drawings and meshes); kept"]


@pytest.mark.slow
def test_a_sigkilled_campaign_leaves_no_worker_and_resumes(tmp_path):
    """A real `archdem campaign` SIGKILLed in its tilt step once a case is stored: no worker
    survives it, and the same command then finishes the step without re-running stored cases."""
    import csv
    import subprocess
    import sys

    from tests.kill import kill_once_stored, outlived, stored_ok

    out = tmp_path / "c"
    study = out / "studies" / "tilt.h5"
    args = [sys.executable, "-m", "dem.cli", "campaign", "--quick", "--steps", "tilt", "--workers", "2",
            "--specimens", "Sh02-Sd020,Sh06-Sd020,Sh1-Sd020", "--out", str(out)]
    kids = kill_once_stored(args, study, workers=2)
    assert not outlived(kids), "workers still running 10 s after the kill"
    before = stored_ok(study)
    assert 1 <= len(before) < 3
    assert not (out / "tilt" / "tilt.csv").exists()
    done = subprocess.run(args, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    after = stored_ok(study)
    assert len(after) == 3 and {k: after[k] for k in before} == before
    with open(out / "tilt" / "tilt.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 3 and all(0.1 < float(r["lambda_dem_reference"]) < 1.0 for r in rows)


def test_a_finished_campaign_folder_keeps_no_lock(tmp_path):
    from dem.campaign.runner import LOCK_FILE, run_campaign

    run_campaign(CampaignContext(out=tmp_path, specimens=select_specimens("Sh02-Sd020"), log=lambda s: None), ["catalogue"])
    assert (tmp_path / "catalogue" / "catalogue.csv").is_file() and not (tmp_path / LOCK_FILE).exists()
