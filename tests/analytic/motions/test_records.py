"""Readers of recorded accelerograms, and the processing functions (analytic/motions/records.py).

The reference values (npts, dt, PGA, time of the peak, sha256) are those of the data
README in tests/data/ground_motions/, computed there independently of this parser.
"""
from __future__ import annotations

import hashlib
import math
from pathlib import Path

import numpy as np
import pytest

from analytic.motions.inputs import SampledMotion
from analytic.motions.records import (
    baseline_correct,
    detect_format,
    load_record,
    read_record,
    resample,
    with_zero_tail,
)
from dem.cli import main
from specimens.constants import G
from foundation.errors import ArchdemInputError

DATA = Path(__file__).resolve().parents[2] / "data" / "ground_motions"

# file: (format, units, npts, dt, PGA, PGA unit, time of PGA [s], sha256) — from the data README
DOCUMENTED = {
    "RSN6_IMPVALL.I_I-ELC180.AT2": ("at2", "g", 5372, 0.01, 0.2808, "g", 2.18,
                                    "ab219fe7bc8060fb5dba31669b5c29a782435bef113eda51ab81b8f6ff05824d"),
    "RSN77_SFERN_PUL164.AT2": ("at2", "g", 4172, 0.01, 1.2190, "g", 7.75,
                               "ea1186e852208172b90d20416fb18e9a9683881ed49fff92299982d73f131b16"),
    "NIS090.AT2": ("at2", "g", 4096, 0.01, 0.5027, "g", 7.09,
                   "6a8c01911bc4de7fa627445da0b39779eafaa346bf2fd4ea9cdc1e65b4158112"),
    "0111a.smc": ("smc", "cm/s2", 6001, 0.005, 104.41, "cm/s2", 10.17,
                  "2d51e2695d367ade03b161e4986c179afaf4edfaec073505e4430081dbf184d3"),
}


@pytest.mark.parametrize("name", sorted(DOCUMENTED))
def test_shared_records_match_documented_values(name):
    fmt, units, npts, dt, pga, pga_unit, t_pga, sha = DOCUMENTED[name]
    path = DATA / name
    assert hashlib.sha256(path.read_bytes()).hexdigest() == sha  # the committed file is the documented one
    rec = load_record(path)
    m = rec.motion
    assert rec.format == fmt and rec.units == units and rec.units_from == "header"
    assert len(m.values) == npts
    assert m.dt == pytest.approx(dt, rel=1e-12)
    factor = G if pga_unit == "g" else 0.01
    # README rounds the PGA to 4 significant digits (g) or 0.01 cm/s^2: half a unit of the last digit
    half_ulp = 0.5 * 10 ** (math.floor(math.log10(pga)) - 3) if pga_unit == "g" else 0.005
    assert abs(m.pga / factor - pga) <= half_ulp + 1e-12
    # the peak sample is where the README says (times there are exact multiples of dt)
    assert int(np.argmax(np.abs(m.values))) == round(t_pga / dt)
    assert m.source == f"{name} ({fmt})"
    assert read_record(path).pga == m.pga


def test_old_and_new_at2_headers_detected(tmp_path):
    # the two header variants of line 4, same samples: identical motion
    body = ["  .1000000E-01  -.2000000E-01   .3000000E-01", "  -.4000000E-01"]
    new = ["PEER NGA STRONG MOTION DATABASE RECORD", "Ev, 1/1/2000, Sta, 90",
           "ACCELERATION TIME SERIES IN UNITS OF G", "NPTS=      4, DT=   .0050 SEC,   "] + body
    old = ["PEER NGA STRONG MOTION DATABASE RECORD", "EV 01/01/00 0000, STA, 090 (X)",
           "ACCELERATION TIME HISTORY IN UNITS OF G", "4    0.0050    NPTS, DT"] + body
    (tmp_path / "new.AT2").write_text("\n".join(new) + "\n")
    (tmp_path / "old.AT2").write_text("\n".join(old))  # and no final newline
    a, b = read_record(tmp_path / "new.AT2"), read_record(tmp_path / "old.AT2")
    assert detect_format(tmp_path / "old.AT2") == "at2"
    expected = np.array([0.01, -0.02, 0.03, -0.04]) * G  # written values times g
    np.testing.assert_allclose(a.values, expected, rtol=1e-15)
    np.testing.assert_array_equal(a.values, b.values)
    assert a.dt == b.dt == 0.005


def test_mangled_line_ends_read_the_same(tmp_path):
    # some copies of AT2 files have \r\r\n line ends (blank lines in between)
    src = (DATA / "NIS090.AT2").read_bytes()
    p = tmp_path / "mangled.AT2"
    p.write_bytes(src.replace(b"\n", b"\r\r\n"))
    np.testing.assert_array_equal(read_record(p).values, read_record(DATA / "NIS090.AT2").values)


# ---------------------------------------------------------------- malformed files
def _lines(name):
    return (DATA / name).read_text().splitlines()


def _malformed(tmp_path):
    """(file name, text, line the message must name or None, words the message must contain)."""
    at2 = _lines("RSN6_IMPVALL.I_I-ELC180.AT2")
    smc = (DATA / "0111a.smc").read_text().splitlines()
    cases = []
    cases.append(("trunc.AT2", "\n".join(at2[:-3]) + "\n", 4, "truncated"))
    wrong = list(at2)
    wrong[3] = wrong[3].replace("5372", "5373")
    cases.append(("npts.AT2", "\n".join(wrong), 4, "5373"))
    bad = list(at2)
    bad[99] = bad[99].replace(bad[99].split()[2], "abc")
    cases.append(("text.AT2", "\n".join(bad), 100, "abc"))
    cases.append(("empty.AT2", "", None, "empty"))
    cases.append(("blank.csv", "\n  \n", None, "empty"))
    cases.append(("unknown.dat", "hello world\nthis is not a record\n", 1, "unknown record format"))
    cases.append(("header.AT2", "\n".join(at2[:3]), 3, "header"))
    cases.append(("trunc.smc", "\n".join(smc[:-10]), 13, "truncated"))
    bad = list(smc)
    bad[40] = bad[40][:10] + "-2.x223E+0" + bad[40][20:]
    cases.append(("text.smc", "\n".join(bad), 41, "-2.x223E+0"))
    esm = _esm_text(np.array([1.0, 2.0, 3.0]), ndata=4)
    cases.append(("ndata.ASC", esm, 6, "truncated"))
    cases.append(("text.csv", "time,acc [g]\n0,0.1\n0.01,0.2\n0.02,x0.3\n", 4, "x0.3"))
    cases.append(("uneven.csv", "time,acc [g]\n0,0.1\n0.01,0.2\n0.02,0\n0.03,0\n0.07,0.3\n", 6, "constant step"))
    cases.append(("nounits.csv", "0,0.1\n0.01,0.2\n0.02,0.3\n", 1, "units"))
    # sanity bounds: a header read as a 1000 s step, a record of a few microseconds, a 5e4 g sample
    slow = list(at2)
    slow[3] = slow[3].replace(".0100", "1000.")
    cases.append(("dt.AT2", "\n".join(slow), 4, "time step 1000 s is outside"))
    cases.append(("short.csv", "time,acc [g]\n0,0.1\n0.001,0.2\n0.002,0.1\n", 2, "less than 0.01 s"))
    cases.append(("tiny.csv", "time,acc [g]\n0,0.1\n0.000005,0.2\n", 2, "outside"))
    cases.append(("peak.csv", "time,acc [g]\n0,0.1\n0.01,50000\n0.02,0\n", 2, "above 20 g"))
    # header fields that are no numbers, or negative (the message names the field)
    for k, (field, value, words) in enumerate([
            ("5372", "-5372", "NPTS must be a positive whole number, got '-5372'"),
            ("5372", "nan", "NPTS must be a positive whole number, got 'nan'"),
            (".0100", "nan", "DT must be a positive time step in s, got 'nan'"),
            (".0100", "-.0100", "DT must be a positive time step in s, got '-.0100'")]):
        h = list(at2)
        h[3] = h[3].replace(field, value)
        cases.append((f"header{k}.AT2", "\n".join(h), 4, words))
    out = []
    for name, text, line, words in cases:
        p = tmp_path / name
        p.write_text(text)
        out.append((p, line, words))
    return out


def test_malformed_files_give_one_line_error_naming_file_and_line(tmp_path):
    for p, line, words in _malformed(tmp_path):
        with pytest.raises(ArchdemInputError) as exc:
            read_record(p)
        msg = str(exc.value)
        assert "\n" not in msg, msg
        assert msg.startswith(f"{p}:" if line is None else f"{p}:{line}:"), msg
        assert words in msg, msg


def test_cli_exit_2_on_malformed_file(tmp_path, capsys):
    p, line, _ = _malformed(tmp_path)[0]
    assert main(["record", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith(f"archdem: error: {p}:{line}:") and "\n" not in err


def test_cli_prints_summary(capsys):
    import json

    assert main(["record", str(DATA / "RSN77_SFERN_PUL164.AT2"), "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["npts"] == 4172 and s["dt"] == 0.01 and s["units"] == "g" and s["format"] == "at2"
    assert s["pga_g"] == pytest.approx(1.2190, abs=5e-5)  # README value, 4 digits
    assert s["pga_ms2"] == pytest.approx(s["pga_g"] * G, rel=1e-12)
    assert s["duration"] == pytest.approx(4171 * 0.01, rel=1e-12)  # time of the last sample


def test_declared_units_conflicting_with_header_rejected(tmp_path):
    with pytest.raises(ArchdemInputError, match="declared"):
        read_record(DATA / "NIS090.AT2", units="cm/s2")
    assert read_record(DATA / "NIS090.AT2", units="g").pga == read_record(DATA / "NIS090.AT2").pga
    with pytest.raises(ArchdemInputError, match="unknown record format"):
        read_record(DATA / "NIS090.AT2", fmt="xyz")


# ---------------------------------------------------------------- round trips
def _esm_text(values_cms2: np.ndarray, dt: float = 0.005, ndata: int | None = None) -> str:
    hdr = [
        "EVENT_NAME: SYNTHETIC", "EVENT_ID: TEST-0001", "NETWORK: XX", "STATION_CODE: ABC", "STREAM: HNE",
        f"NDATA: {len(values_cms2) if ndata is None else ndata}", f"SAMPLING_INTERVAL_S: {dt:.6f}",
        "UNITS: cm/s^2", f"PGA_CM/S^2: {np.max(np.abs(values_cms2)):.6f}", "DATA_TYPE: ACCELERATION",
        "HEADER_FORMAT: DYNA 1.2", "DATA_LICENSE: CC-BY4_0", "USER1:", "USER2:",
    ]
    return "\n".join(hdr + [f"{v:.6e}" for v in values_cms2]) + "\n"


def test_esm_round_trip(tmp_path):
    dt = 0.005
    t = dt * np.arange(801)
    a = 250.0 * np.sin(2 * np.pi * 2.0 * t) * np.exp(-t)  # cm/s^2
    p = tmp_path / "XX.ABC..HNE.D.TEST.ACC.MP.ASC"
    p.write_text(_esm_text(a, dt))
    rec = load_record(p)
    assert rec.format == "esm" and rec.units == "cm/s2"
    # written with 7 significant digits: relative error < 5e-7
    np.testing.assert_allclose(rec.motion.values, a / 100.0, rtol=5e-7, atol=1e-12)
    assert rec.motion.dt == dt and rec.motion.name == "SYNTHETIC XX.ABC HNE"


@pytest.mark.parametrize("header,units,factor", [
    ("time [s],acceleration [g]", None, G),
    ("t (s); a (cm/s^2)", None, 0.01),
    ("", "mm/s2", 1e-3),
    ("# a comment line\ntime acc", "m/s2", 1.0),
])
def test_csv_round_trip(tmp_path, header, units, factor):
    dt = 0.01
    t = dt * np.arange(301)
    a = 0.3 * np.sin(2 * np.pi * 1.5 * t)
    sep = ";" if ";" in header else ("," if "," in header or not header else " ")
    lines = ([header] if header else []) + [f"{ti:.4f}{sep}{ai:.9e}" for ti, ai in zip(t, a)]
    p = tmp_path / "motion.csv"
    p.write_text("\n".join(lines) + "\n")
    m = read_record(p, units=units)
    assert m.dt == pytest.approx(dt, rel=1e-12)  # (t_last - t_0)/(n-1) with exact 4-digit times
    np.testing.assert_allclose(m.values, a * factor, rtol=1e-9, atol=1e-15)  # 10 significant digits written


# ---------------------------------------------------------------- processing
def test_baseline_correction_removes_polynomial_drift():
    m = read_record(DATA / "RSN6_IMPVALL.I_I-ELC180.AT2")
    t = m.times
    for order, drift in ((1, 0.05 + 0 * t), (2, 0.05 - 0.002 * t)):
        c = baseline_correct(m, order)
        # identity: adding a polynomial of degree order-1 to the acceleration adds a polynomial
        # of degree `order` to the (trapezoid-exact) velocity, which the fit removes exactly
        c2 = baseline_correct(SampledMotion(m.values + drift, m.dt), order)
        np.testing.assert_allclose(c2.values, c.values, atol=1e-9 * m.pga)
        # projection: the corrected velocity has no component left on t, ..., t^order (a constant
        # velocity cannot be removed through the acceleration; v(0) = 0 by the integration)
        from numpy.polynomial import Polynomial
        from scipy.integrate import cumulative_trapezoid

        v = cumulative_trapezoid(c.values, t, initial=0.0)
        coef = Polynomial.fit(t, v, order).convert().coef
        assert np.max(np.abs(coef[1:])) < 1e-9  # m/s per s^k; v itself is O(0.3 m/s): round-off only
    with pytest.raises(ArchdemInputError):
        baseline_correct(m, 0)


def test_resample_up_is_the_interpolated_signal_and_keeps_pga():
    m = read_record(DATA / "RSN6_IMPVALL.I_I-ELC180.AT2")
    r = resample(m, 0.001)  # integer ratio 10: every record sample is on the new grid
    assert r.dt == 0.001 and len(r.values) == 10 * (len(m.values) - 1) + 1
    assert r.pga == pytest.approx(m.pga, rel=1e-12)
    np.testing.assert_allclose(r.values, m.acceleration(r.times), rtol=0, atol=1e-12)
    # non-integer ratio (a 240 Hz simulator step): the documented bound on the PGA loss
    r2 = resample(m, 1 / 240)
    bound = np.max(np.abs(np.diff(m.values))) * (1 / 240) / (2 * m.dt)
    assert 0 <= m.pga - r2.pga <= bound
    assert r2.duration <= m.duration + 1e-12


def test_resample_down_keeps_low_frequency_content():
    dt = 0.001
    t = dt * np.arange(5001)
    m = SampledMotion(np.sin(2 * np.pi * 1.0 * t), dt)
    r = resample(m, 0.01)
    inner = slice(50, -50)  # away from the filter's edge effects
    # a 1 Hz sine is far below the new Nyquist (50 Hz): the anti-alias FIR passes it (< 0.2 %)
    np.testing.assert_allclose(r.values[inner], np.sin(2 * np.pi * r.times[inner]), atol=2e-3)


def test_zero_tail():
    m = read_record(DATA / "NIS090.AT2")
    z = with_zero_tail(m, 2.0)
    assert len(z.values) == len(m.values) + 200
    assert z.duration == pytest.approx(m.duration + 2.0, rel=1e-12)
    assert z.pga == m.pga and np.all(z.values[len(m.values):] == 0)
    s = z.to_pga(0.3 * G)  # scaling already in SampledMotion
    assert s.pga == pytest.approx(0.3 * G, rel=1e-12)


# ------------------------------------------------------------------ random corruption of real files
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from analytic.motions.records import MAX_RECORD_PGA_G, MIN_RECORD_S, RECORD_DT_RANGE  # noqa: E402

_BAD_TOKENS = ["nan", "inf", "-inf", "-1", "0", "1e30", "1e-30", "-5372", "x", "", "NPTS=", "DT=nan", "1,,2", "\x00", "é"]
_EDIT = st.tuples(st.sampled_from(["token", "delete", "duplicate", "truncate", "byte", "swap"]),
                  st.floats(0, 1), st.floats(0, 1), st.sampled_from(_BAD_TOKENS), st.integers(0, 255))


def _corrupt(data: bytes, edits) -> bytes:
    """Apply random edits to a file: a token replaced, a line deleted or repeated, the file cut,
    a byte changed, two lines swapped."""
    for kind, f1, f2, tok, byte in edits:
        lines = data.split(b"\n")
        i, j = int(f1 * (len(lines) - 1)), int(f2 * (len(lines) - 1))
        if kind == "token":
            words = lines[i].split()
            if words:
                words[int(f2 * (len(words) - 1))] = tok.encode()
            lines[i] = b" ".join(words)
        elif kind == "delete":
            del lines[i]
        elif kind == "duplicate":
            lines.insert(i, lines[i])
        elif kind == "swap":
            lines[i], lines[j] = lines[j], lines[i]
        data = b"\n".join(lines)
        if kind == "truncate":
            data = data[:int(f1 * len(data))]
        elif kind == "byte" and data:
            k = int(f1 * (len(data) - 1))
            data = data[:k] + bytes([byte]) + data[k + 1:]
    return data


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(name=st.sampled_from(sorted(DOCUMENTED)), edits=st.lists(_EDIT, min_size=1, max_size=4))
def test_a_corrupted_record_is_read_sanely_or_refused_in_one_line(tmp_path, name, edits):
    """The real files, randomly damaged: each is either read into a motion within the stated
    bounds, or refused with one line naming the file; never another exception."""
    path = tmp_path / name
    path.write_bytes(_corrupt((DATA / name).read_bytes(), edits))
    try:
        m = read_record(path)
    except ArchdemInputError as exc:
        assert "\n" not in str(exc) and str(exc).startswith(str(path))
        return
    assert RECORD_DT_RANGE[0] <= m.dt <= RECORD_DT_RANGE[1]
    assert m.duration >= MIN_RECORD_S and np.all(np.isfinite(m.values))
    assert np.max(np.abs(m.values)) / G <= MAX_RECORD_PGA_G


@pytest.mark.parametrize("values, scale, match", [
    (np.zeros(1000), 1.0, "is all zeros"),
    (np.sin(np.arange(1000) * 0.3), 3e-10 * G, "peaks at 3e-10 g"),
    (np.sin(np.arange(1000) * 0.3), 0.0, "is all zeros"),
])
def test_a_motion_below_an_accelerometers_resolution_is_refused(values, scale, match):
    """A record of zeros, or scaled far below 1e-6 g, moves nothing: refused, not simulated for minutes."""
    with pytest.raises(ArchdemInputError, match=match):
        SampledMotion(values, 0.01, scale)
    m = SampledMotion(np.sin(np.arange(1000) * 0.3), 0.01)
    with pytest.raises(ArchdemInputError, match="peaks at"):
        m.scaled(1e-9)
    assert m.scaled(2e-6 * G).pga == pytest.approx(2e-6 * G)  # just above the floor: a motion


def test_the_shipped_example_record_is_the_documented_one_and_unknown_names_are_refused():
    """The record examples use ships inside the package (they run from any folder): the same bytes as the
    test data's copy, whose sha256 the data README documents."""
    from analytic.motions.records import EXAMPLE_RECORDS, example_record

    for name in EXAMPLE_RECORDS:
        path = example_record(name)
        assert path.is_file() and path.is_absolute()
        assert hashlib.sha256(path.read_bytes()).hexdigest() == DOCUMENTED[name][-1]
    assert example_record() == example_record("RSN77_SFERN_PUL164.AT2")
    with pytest.raises(ArchdemInputError, match="no shipped record"):
        example_record("NIS090.AT2")


def test_the_shipped_record_is_declared_package_data():
    """A wheel carries only the data files pyproject.toml declares: the example record must be among them."""
    import tomllib

    from analytic.motions.records import EXAMPLE_RECORDS, example_record

    root = Path(__file__).resolve().parents[3]
    globs = tomllib.loads((root / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]["analytic"]
    for name in EXAMPLE_RECORDS:
        rel = example_record(name).relative_to(root / "analytic")
        assert any(rel.match(g) for g in globs), (rel, globs)


# ------------------------------------------------------------------ bounded work (docs/decisions/010-input-rules.md)
def _refused_quickly(path, match, **kw):
    """The reader refuses ``path`` in one line, with under 1 s of CPU time."""
    import time

    t0 = time.process_time()
    with pytest.raises(ArchdemInputError, match=match) as exc:
        load_record(path, **kw)
    assert time.process_time() - t0 < 1.0
    assert "\n" not in str(exc.value)
    return str(exc.value)


def test_a_record_file_larger_than_the_byte_limit_is_refused_by_its_size(tmp_path):
    from analytic.motions.records import MAX_RECORD_BYTES

    # the probe's file: 10 million samples at 5 ms (~140 MB); a sparse file of that size stands for it
    p = tmp_path / "ten-million.csv"
    with open(p, "wb") as f:
        f.write(b"time, acc [g]\n0,0.1\n0.005,0.2\n0.01,0.1\n")
        f.truncate(10_000_000 * 14)
    msg = _refused_quickly(p, "more than the 64 MB a record file may have")
    assert "cut the record" in msg and MAX_RECORD_BYTES == 64 * 2**20


def test_dev_zero_is_read_up_to_the_byte_limit_only(capsys):
    import subprocess
    import sys

    if not Path("/dev/zero").exists():
        pytest.skip("no /dev/zero")

    def cap_memory():  # a reader without a limit fails here, not by filling the machine's memory
        import resource

        resource.setrlimit(resource.RLIMIT_AS, (4 * 2**30, 4 * 2**30))

    r = subprocess.run([sys.executable, "-m", "dem.cli", "record", "/dev/zero"], capture_output=True, text=True,
                       timeout=30, preexec_fn=cap_memory)
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "64 MB" in r.stderr and r.stdout == ""
    _refused_quickly("/dev/zero", "holds more than the 64 MB")


def test_a_csv_record_above_the_sample_limit_is_refused_before_parsing(tmp_path):
    from analytic.motions.records import MAX_RECORD_SAMPLES

    p = tmp_path / "long.csv"
    p.write_bytes(b"time, acc [g]\n" + b"0,0.1\n" * (MAX_RECORD_SAMPLES + 1))
    _refused_quickly(p, f"{MAX_RECORD_SAMPLES + 1} samples, more than the {MAX_RECORD_SAMPLES} a record may hold")


@pytest.mark.parametrize("npts, dt, words", [(2_000_000, 0.005, "samples, more than the 1000000"),
                                             (200_000, 0.01, "lasts 1999.99 s, more than the 1200 s")])
def test_a_header_declaring_too_many_samples_or_seconds_is_refused_at_the_header(tmp_path, npts, dt, words):
    p = tmp_path / "long.AT2"
    p.write_text("PEER NGA STRONG MOTION DATABASE RECORD\nEv, 1/1/2000, Sta, 90\n"
                 f"ACCELERATION TIME SERIES IN UNITS OF G\nNPTS= {npts}, DT= {dt} SEC,\n  .1 .2 .3\n")
    msg = _refused_quickly(p, words)
    assert msg.startswith(f"{p}:4: ") and "cut the record" in msg


def test_an_absurd_sample_is_refused_without_a_numpy_warning(tmp_path):
    import warnings

    p = tmp_path / "absurd.csv"
    p.write_text("time, acc [g]\n0,0\n0.01,1e308\n0.02,0\n0.03,0.1\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _refused_quickly(p, "peak acceleration 1e\\+308 g is above 20 g")
    assert caught == []


def test_the_simulated_time_of_a_run_is_bounded():
    from dem.experiments.shake.run import MAX_RUN_S, ShakeProtocol

    m = SampledMotion(np.full(400_001, 0.1), 0.005)  # 2000 s built by hand, past the readers
    with pytest.raises(ArchdemInputError, match=f"more than {MAX_RUN_S:g} s; cut the record or give --duration"):
        ShakeProtocol().total_duration(m)
    assert ShakeProtocol(duration=5.0).total_duration(m) == 5.0
    assert ShakeProtocol(tail=1.0).total_duration(SampledMotion(np.full(1001, 0.1), 0.005)) == 6.0
