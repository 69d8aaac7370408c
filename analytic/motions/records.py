"""Recorded accelerograms: readers, units, baseline correction, resampling, zero tail.

Formats (see the ground-motion data README kept with the test data):

* ``at2`` — PEER NGA ``.AT2``, both header variants of line 4
  (``NPTS=   5372, DT=   .0100 SEC,`` and the old ``4096    0.0100    NPTS, DT``);
* ``smc`` — USGS ``.smc`` (fixed-width; corrected or uncorrected accelerogram, cm/s^2);
* ``esm`` — ESM / ITACA ASCII (DYNA 1.2 ``KEY: value`` header, then the samples);
* ``csv`` — two columns ``time, acceleration`` (comma, semicolon or blank separated;
  optional header line, ``#`` comments). Units from a header such as ``acc [g]`` or
  declared with ``units=``. Times must be equally spaced; a first time t0 != 0 is
  dropped (the motion starts at t = 0).

Every reader returns acceleration in m/s^2 as :class:`analytic.motions.inputs.SampledMotion`
(``g`` is converted with :data:`specimens.constants.G`). Units written in a file win; a
declared ``units`` that contradicts the file is an error (it is almost always a mistake).
Malformed files raise :class:`ArchdemInputError` with a one-line message
``FILE:LINE: problem``; so are files past the size bounds (:data:`MAX_RECORD_BYTES`,
:data:`MAX_RECORD_SAMPLES`, :data:`MAX_RECORD_S`), before they are parsed. This module does file
I/O only; the processing functions (:func:`baseline_correct`, :func:`resample`, :func:`with_zero_tail`)
are pure.
"""
from __future__ import annotations

import itertools
import math
import os
import re
import stat
from dataclasses import dataclass, replace
from fractions import Fraction
from pathlib import Path

import numpy as np
from numpy.polynomial import Polynomial

from analytic.motions.inputs import MIN_PEAK_ACCELERATION, GroundMotion, SampledMotion, SinePulse
from specimens.constants import G
from foundation.errors import ArchdemInputError

FORMATS = ("at2", "smc", "esm", "csv")

# canonical unit name -> factor to m/s^2
UNIT_FACTORS = {"g": G, "m/s2": 1.0, "cm/s2": 0.01, "mm/s2": 0.001}

_UNIT_ALIASES = {
    "g": "g", "gs": "g", "g's": "g",
    "m/s2": "m/s2", "m/s^2": "m/s2", "m/s/s": "m/s2", "m/sec2": "m/s2", "m/sec^2": "m/s2", "m/sec/sec": "m/s2",
    "ms-2": "m/s2", "m/s**2": "m/s2",
    "cm/s2": "cm/s2", "cm/s^2": "cm/s2", "cm/s/s": "cm/s2", "cm/sec2": "cm/s2", "cm/sec^2": "cm/s2",
    "cm/sec/sec": "cm/s2", "gal": "cm/s2", "cms-2": "cm/s2", "cm/s**2": "cm/s2",
    "mm/s2": "mm/s2", "mm/s^2": "mm/s2", "mm/s/s": "mm/s2", "mm/sec2": "mm/s2", "mm/sec^2": "mm/s2",
    "mm/s**2": "mm/s2",
}


def canonical_units(text: str) -> str | None:
    """``'g'``, ``'m/s2'``, ``'cm/s2'`` or ``'mm/s2'`` for a unit string, else None."""
    key = re.sub(r"\s+", "", str(text)).lower().rstrip(".,;")
    return _UNIT_ALIASES.get(key)


@dataclass(frozen=True)
class Record:
    """A record as read: the motion [m/s^2] plus what the file said about it."""

    motion: SampledMotion
    format: str
    units: str  # canonical unit name of the file's numbers
    units_from: str  # "header" or "declared"
    path: str


class _Src:
    """The lines of one file, with error messages naming file and 1-based line."""

    def __init__(self, path: Path):
        self.path = path
        try:
            with open(path, "rb") as fh:  # at most MAX_RECORD_BYTES + 1 bytes, never the whole of /dev/zero
                st = os.fstat(fh.fileno())
                if stat.S_ISREG(st.st_mode) and st.st_size > MAX_RECORD_BYTES:
                    raise self._too_big(f"is {st.st_size / 2**20:.0f} MB, more")
                data = fh.read(MAX_RECORD_BYTES + 1)
                if len(data) > MAX_RECORD_BYTES:
                    raise self._too_big("holds more")
            self._check_lines(data)
            # as text mode with universal newlines: \r\n and \r end lines too
            self.lines = data.decode("utf-8", errors="replace").splitlines()
        except FileNotFoundError:
            raise ArchdemInputError(f"{path}: no such file") from None
        except IsADirectoryError:
            raise ArchdemInputError(f"{path}: is a directory, not a record file") from None
        except OSError as exc:
            raise ArchdemInputError(f"{path}: cannot read ({exc.strerror})") from None

    def _check_lines(self, data: bytes) -> None:
        """Refuse, before the text is split into lines (a second per 10 million), a file with more lines
        that start with data than a record holds samples: each such line holds one sample or more, and
        a header is at most :data:`MAX_HEADER_LINES`."""
        if data.count(b"\n") + data.count(b"\r") <= MAX_RECORD_SAMPLES:
            return
        b = np.frombuffer(data, np.uint8)
        starts = np.concatenate(([0], np.flatnonzero((b == 10) | (b == 13)) + 1))
        first = b[starts[starts < len(b)]]
        n = int(np.count_nonzero(~np.isin(first, np.frombuffer(b" \t\r\n\f\v#", np.uint8))))
        if n - MAX_HEADER_LINES > MAX_RECORD_SAMPLES:
            raise ArchdemInputError(f"{self.path}: {n} non-blank lines, more than the {MAX_RECORD_SAMPLES} samples a "
                                    "record may hold; cut the record")

    def _too_big(self, what: str) -> ArchdemInputError:
        return ArchdemInputError(f"{self.path}: {what} than the {MAX_RECORD_BYTES // 2**20} MB a record file may "
                                 "have (not a record?); cut the record")

    def error(self, lineno: int | None, msg: str) -> ArchdemInputError:
        where = f"{self.path}:{lineno}" if lineno else f"{self.path}"
        return ArchdemInputError(f"{where}: {msg}")

    def nonblank(self, start: int = 0, limit: int | None = None) -> list[tuple[int, str]]:
        """(1-based line number, text) of the non-blank lines from index ``start`` (the first ``limit``)."""
        return list(itertools.islice(((i + 1, s) for i, s in enumerate(self.lines[start:], start) if s.strip()), limit))


def _float(src: _Src, lineno: int, token: str) -> float:
    try:
        v = float(token)
    except ValueError:
        raise src.error(lineno, f"not a number: {token.strip()!r}") from None
    if not math.isfinite(v):
        raise src.error(lineno, f"not a finite number: {token.strip()!r}")
    return v


def _check_count(src: _Src, values: list[float], npts: int, npts_line: int, last_line: int | None) -> None:
    if len(values) != npts:
        what = "truncated data" if len(values) < npts else "more samples than declared"
        end = f" (data end at line {last_line})" if last_line else " (no data lines)"
        raise src.error(npts_line, f"{what}: header declares {npts} samples, file has {len(values)}{end}")


def _resolve_units(src: _Src, header_units: str | None, declared: str | None, line: int | None) -> tuple[str, str]:
    if declared is not None:
        d = canonical_units(declared)
        if d is None:
            raise ArchdemInputError(f"unknown units {declared!r}; use one of {', '.join(UNIT_FACTORS)}")
    else:
        d = None
    if header_units is not None:
        if d is not None and d != header_units:
            raise src.error(line, f"file gives units {header_units}, but units {d} were declared")
        return header_units, "header"
    if d is None:
        raise src.error(line, f"units not given in the file; declare them (one of {', '.join(UNIT_FACTORS)})")
    return d, "declared"


#: Sanity bounds of a record file (strong-motion records are sampled at 50-1000 Hz, last seconds to
#: minutes and peak below 5 g): beyond them the file is misread (a wrong unit, a wrong header).
RECORD_DT_RANGE = (1e-5, 1.0)  # s
MIN_RECORD_S = 0.01  # s: 20 steps of the default simulator step
MAX_RECORD_PGA_G = 20.0
#: Size bounds of a record file, each far above a real one (docs/decisions/010-input-rules.md#record-size-and-run-length):
#: they bound the work of a reader and of a run before any of it is done.
MAX_RECORD_BYTES = 64 * 2**20  # real record files are < 5 MB; 1 M samples of a 2-column CSV fit in it
MAX_RECORD_SAMPLES = 1_000_000  # 10 x a real record (< 100 000 samples)
MAX_RECORD_S = 1200.0  # s: twice a real record (< 600 s)
#: Most header lines of a record file (an SMC's text, integer, real and comment lines; an ESM's keys).
MAX_HEADER_LINES = 1000


def _check_size(src: _Src, lineno: int | None, npts: int, dt: float | None = None) -> None:
    """Refuse a record with more samples, or lasting longer, than the bounds above."""
    if npts > MAX_RECORD_SAMPLES:
        raise src.error(lineno, f"{npts} samples, more than the {MAX_RECORD_SAMPLES} a record may hold; "
                                "cut the record")
    if dt is not None and RECORD_DT_RANGE[0] <= dt <= RECORD_DT_RANGE[1] and (npts - 1) * dt > MAX_RECORD_S:
        raise src.error(lineno, f"the record lasts {(npts - 1) * dt:g} s, more than the {MAX_RECORD_S:g} s a record "
                                "may last; cut the record")


def _motion(src: _Src, values: list[float], dt: float, units: str, name: str, fmt: str, dt_line: int) -> SampledMotion:
    if not (math.isfinite(dt) and dt > 0):
        raise src.error(dt_line, f"time step must be positive, got {dt!r}")
    if not RECORD_DT_RANGE[0] <= dt <= RECORD_DT_RANGE[1]:
        raise src.error(dt_line, f"time step {dt:g} s is outside {RECORD_DT_RANGE[0]:g}-{RECORD_DT_RANGE[1]:g} s "
                                 "(a misread header?)")
    if len(values) < 2:
        raise src.error(dt_line, f"a record needs at least 2 samples, got {len(values)}")
    if (len(values) - 1) * dt < MIN_RECORD_S:
        raise src.error(dt_line, f"the record lasts {(len(values) - 1) * dt:g} s, less than {MIN_RECORD_S:g} s")
    _check_size(src, dt_line, len(values), dt)
    raw = np.asarray(values, dtype=float)
    # the peak in g before any scaling: a factor to g is <= 1, so an absurd value (1e308 g) cannot overflow
    pga_g = float(np.max(np.abs(raw))) * (UNIT_FACTORS[units] / G)
    if not (math.isfinite(pga_g) and pga_g <= MAX_RECORD_PGA_G):
        raise src.error(dt_line, f"peak acceleration {pga_g:.3g} g is above {MAX_RECORD_PGA_G:g} g (wrong units?)")
    v = raw * UNIT_FACTORS[units]
    return SampledMotion(v, dt, name=" ".join(name.split()), source=f"{src.path.name} ({fmt})")


# ----------------------------------------------------------------------------- PEER AT2
_NPTS_RE = re.compile(r"NPTS\s*=\s*([^,\s]*)", re.IGNORECASE)
_DT_RE = re.compile(r"DT\s*=\s*([^,\s]*)", re.IGNORECASE)

def _read_at2(src: _Src, units: str | None) -> Record:
    rows = src.nonblank()
    if len(rows) < 4:
        raise src.error(rows[-1][0] if rows else None, "AT2 file ends inside its 4-line header")
    (l_title, _), (l_desc, desc), (l_q, qty), (l_n, nline) = rows[:4]
    m = re.search(r"UNITS\s+OF\s+([A-Za-z/^*0-9 .]+?)\s*(?:[.,;]|$)", qty, re.IGNORECASE)
    if "ACCELERATION" not in qty.upper():
        raise src.error(l_q, f"not an acceleration record: {qty.strip()!r}")
    header_units = None
    if m:
        header_units = canonical_units(m.group(1))
        if header_units is None:
            raise src.error(l_q, f"unknown acceleration units {m.group(1)!r}")
    mn, md = _NPTS_RE.search(nline), _DT_RE.search(nline)
    if mn or md:  # "NPTS=   5372, DT=   .0100 SEC,"
        if not (mn and md):
            raise src.error(l_n, f"cannot read NPTS and DT from {nline.strip()!r}")
        npts_s, dt_s = mn.group(1), md.group(1)
    else:  # old NGA: "4096    0.0100    NPTS, DT"
        tok = nline.replace(",", " ").split()
        if len(tok) < 2 or "NPTS" not in nline.upper():
            raise src.error(l_n, f"cannot read NPTS and DT from {nline.strip()!r}")
        npts_s, dt_s = tok[0], tok[1]
    if not npts_s.isdigit() or int(npts_s) < 1:
        raise src.error(l_n, f"NPTS must be a positive whole number, got {npts_s!r}")
    npts = int(npts_s)
    try:
        dt = float(dt_s)
    except ValueError:
        dt = math.nan
    if not (math.isfinite(dt) and dt > 0):
        raise src.error(l_n, f"DT must be a positive time step in s, got {dt_s!r}")
    _check_size(src, l_n, npts, dt)
    values: list[float] = []
    last = None
    for ln, text in rows[4:]:
        values.extend(_float(src, ln, t) for t in text.split())
        last = ln
    _check_count(src, values, npts, l_n, last)
    u, how = _resolve_units(src, header_units, units, l_q)
    return Record(_motion(src, values, dt, u, desc, "at2", l_n), "at2", u, how, str(src.path))


# ----------------------------------------------------------------------------- USGS SMC
def _fixed(src: _Src, lineno: int, text: str, width: int, count: int, conv) -> list:
    out = []
    for k in range(count):
        field = text[k * width:(k + 1) * width]
        if not field.strip():
            raise src.error(lineno, f"missing field {k + 1} of {count} (width {width})")
        try:
            out.append(conv(field))
        except ValueError:
            raise src.error(lineno, f"not a number in field {k + 1}: {field.strip()!r}") from None
    return out


def _read_smc(src: _Src, units: str | None) -> Record:
    L = src.lines
    n_hdr = 11 + 6 + 10
    if len(L) < n_hdr:
        raise src.error(len(L) or None, f"SMC file ends inside its {n_hdr}-line header")
    kind = L[0].upper()
    if "ACCELEROGRAM" not in kind or "RAW" in kind:
        raise src.error(1, f"not a corrected/uncorrected SMC accelerogram: {L[0].strip()!r}")
    ints: list[int] = []
    for i in range(11, 17):
        ints += _fixed(src, i + 1, L[i], 10, 8, int)
    reals: list[float] = []
    for i in range(17, 27):
        reals += _fixed(src, i + 1, L[i], 15, 5, float)
    n_comments, npts = ints[15], ints[16]
    if n_comments < 0 or npts <= 0 or npts == ints[0]:
        raise src.error(14, f"bad comment count {n_comments} or sample count {npts} in the integer header")
    sps = reals[1]
    if not (0 < sps < 1e30):
        raise src.error(18, f"bad sampling rate {sps!r} samples/s in the real header")
    _check_size(src, 13, npts, 1.0 / sps)
    start = n_hdr + n_comments
    if len(L) < start:
        raise src.error(len(L), f"file ends inside its {n_comments} comment lines")
    for i in range(n_hdr, start):
        if not L[i].startswith("|"):
            raise src.error(i + 1, "expected a comment line starting with '|'")
    values: list[float] = []
    last = None
    for i in range(start, len(L)):
        text = L[i].rstrip()
        if not text.strip():
            continue
        for k in range(0, len(text), 10):
            field = text[k:k + 10]
            if field.strip():
                values.append(_float(src, i + 1, field))
        last = i + 1
    _check_count(src, values, npts, 13, last)
    u, how = _resolve_units(src, "cm/s2", units, 1)
    station = L[5].split("component")[0].replace("station =", "").strip()
    comp = L[5].split("=")[-1].strip() if "component" in L[5] else ""
    event = re.sub(r"^[\d\s]+", "", L[3]).strip()
    name = ", ".join(x for x in (event, station, comp) if x)
    return Record(_motion(src, values, 1.0 / sps, u, name, "smc", 18), "smc", u, how, str(src.path))


# ----------------------------------------------------------------------------- ESM ASCII
_KEY_RE = re.compile(r"^\s*([A-Za-z0-9_/^.\-]+)\s*:\s*(.*?)\s*$")


def _is_float(s: str) -> bool:
    try:
        float(s.split()[0])
        return True
    except (ValueError, IndexError):
        return False


def _read_esm(src: _Src, units: str | None) -> Record:
    hdr: dict[str, tuple[int, str]] = {}
    rows = src.nonblank()
    k = 0
    for k, (ln, text) in enumerate(rows):
        if _is_float(text):
            break
        m = _KEY_RE.match(text)
        if not m:
            raise src.error(ln, f"expected 'KEY: value' in the ESM header, got {text.strip()[:40]!r}")
        hdr[m.group(1).upper()] = (ln, m.group(2))
    else:
        k = len(rows)
    for key in ("SAMPLING_INTERVAL_S", "NDATA"):
        if key not in hdr:
            raise src.error(rows[k - 1][0] if k else None, f"ESM header lacks {key}")
    if "DATA_TYPE" in hdr and "ACCELERATION" not in hdr["DATA_TYPE"][1].upper():
        raise src.error(hdr["DATA_TYPE"][0], f"not an acceleration record: DATA_TYPE {hdr['DATA_TYPE'][1]!r}")
    l_n, n_s = hdr["NDATA"]
    try:
        npts = int(n_s)
    except ValueError:
        raise src.error(l_n, f"NDATA is not an integer: {n_s!r}") from None
    l_dt, dt_s = hdr["SAMPLING_INTERVAL_S"]
    dt = _float(src, l_dt, dt_s)
    _check_size(src, l_n, npts, dt)
    header_units, l_u = None, None
    if "UNITS" in hdr:
        l_u, u_s = hdr["UNITS"]
        header_units = canonical_units(u_s)
        if header_units is None:
            raise src.error(l_u, f"unknown acceleration units {u_s!r}")
    values: list[float] = []
    last = None
    for ln, text in rows[k:]:
        values.extend(_float(src, ln, t) for t in text.split())
        last = ln
    _check_count(src, values, npts, l_n, last)
    u, how = _resolve_units(src, header_units, units, l_u or l_n)
    get = lambda key: hdr.get(key, (0, ""))[1]  # noqa: E731
    station = ".".join(s for s in (get("NETWORK"), get("STATION_CODE")) if s)
    name = " ".join(s for s in (get("EVENT_NAME") or get("EVENT_ID"), station, get("STREAM")) if s)
    return Record(_motion(src, values, dt, u, name, "esm", l_dt), "esm", u, how, str(src.path))


# ----------------------------------------------------------------------------- CSV
_SPLIT_RE = re.compile(r"[,;\s]+")


def _read_csv(src: _Src, units: str | None) -> Record:
    header_units, l_hdr = None, None
    t: list[float] = []
    a: list[float] = []
    rows_t: list[int] = []
    first_data = None
    if len(src.lines) - 1 > MAX_RECORD_SAMPLES:  # refused before parsing a million lines; one may be the header
        n_rows = sum(bool(x) and not x.startswith("#") for x in map(str.strip, src.lines))
        if n_rows - 1 > MAX_RECORD_SAMPLES:
            _check_size(src, None, n_rows - 1)
    for ln, text in src.nonblank():
        s = text.strip()
        if s.startswith("#"):
            continue
        tok = [x for x in _SPLIT_RE.split(s) if x]
        if first_data is None and not _is_float(tok[0]):
            if l_hdr is not None:
                raise src.error(ln, f"not a number: {tok[0]!r}")
            l_hdr = ln  # one header line: look for the acceleration units in it
            cols = [c.strip() for c in re.split(r"[,;\t]", s)] if re.search(r"[,;\t]", s) else s.split()
            if len(cols) >= 2:
                m = re.search(r"[\[(]\s*([^\])]+?)\s*[\])]", cols[1])
                if m:
                    header_units = canonical_units(m.group(1))
                    if header_units is None:
                        raise src.error(ln, f"unknown acceleration units {m.group(1)!r} in the header")
            continue
        if len(tok) != 2:
            raise src.error(ln, f"expected 2 columns (time, acceleration), got {len(tok)}")
        rows_t.append(ln)
        t.append(_float(src, ln, tok[0]))
        a.append(_float(src, ln, tok[1]))
        first_data = first_data or ln
    if len(t) < 2:
        raise src.error(first_data or l_hdr, f"a record needs at least 2 samples, got {len(t)}")
    tt = np.asarray(t)
    steps = np.diff(tt)
    ref = float(np.median(steps))
    # times are written with a few digits: allow 0.1 % of the step of rounding per step
    bad = np.nonzero(np.abs(steps - ref) > 1e-3 * abs(ref))[0]
    if ref <= 0 or len(bad):
        i = int(bad[0]) + 1 if len(bad) else 1
        raise src.error(rows_t[i], f"times must increase with a constant step (step {steps[i - 1]:g} s, "
                                   f"usual step {ref:g} s)")
    dt = float((tt[-1] - tt[0]) / (len(tt) - 1))
    u, how = _resolve_units(src, header_units, units, l_hdr or first_data)
    return Record(_motion(src, a, dt, u, src.path.stem, "csv", first_data), "csv", u, how, str(src.path))


_READERS = {"at2": _read_at2, "smc": _read_smc, "esm": _read_esm, "csv": _read_csv}


def detect_format(src_or_path) -> str:
    """Format of a record file from its content; the extension only when the content is inconclusive."""
    src = src_or_path if isinstance(src_or_path, _Src) else _Src(Path(src_or_path))
    rows = src.nonblank(limit=80)  # the head tells
    if not rows:
        raise src.error(None, "empty file")
    if "ACCELEROGRAM" in src.lines[0].upper() and len(src.lines) > 12 and re.match(r"^\s*-?\d+(\s+-?\d+){7}\s*$", src.lines[11]):
        return "smc"
    if len(rows) >= 4 and ("NPTS" in rows[3][1].upper()) and "UNITS OF" in rows[2][1].upper():
        return "at2"
    head = [r[1] for r in rows[:80]]
    if sum(bool(_KEY_RE.match(h)) and not _is_float(h) for h in head) >= 2 and any(h.strip().upper().startswith("NDATA") for h in head):
        return "esm"
    data = [h for h in head if not h.strip().startswith("#")]
    if data and sum(len([x for x in _SPLIT_RE.split(h.strip()) if x]) == 2 and _is_float(h) for h in data[:5]) >= min(2, len(data)):
        return "csv"
    ext = {".at2": "at2", ".smc": "smc", ".asc": "esm", ".csv": "csv"}.get(src.path.suffix.lower())
    if ext:  # content inconclusive (e.g. a damaged header): trust the extension, the reader says what is wrong
        return ext
    raise src.error(rows[0][0], "unknown record format (not PEER AT2, USGS SMC, ESM ASCII or 2-column CSV); give the format")


def load_record(path: str | Path, fmt: str = "auto", units: str | None = None) -> Record:
    """Read a record file; ``fmt`` is ``auto`` or one of :data:`FORMATS`; ``units`` declared units."""
    fmt = (fmt or "auto").lower()
    if fmt != "auto" and fmt not in FORMATS:
        raise ArchdemInputError(f"unknown record format {fmt!r}; use auto, {', '.join(FORMATS)}")
    src = _Src(Path(path))
    if not any(s.strip() for s in src.lines):
        raise src.error(None, "empty file")
    if fmt == "auto":
        fmt = detect_format(src)
    return _READERS[fmt](src, units)


def read_record(path: str | Path, fmt: str = "auto", units: str | None = None) -> SampledMotion:
    """The accelerogram in ``path`` as a :class:`SampledMotion` [m/s^2]."""
    return load_record(path, fmt, units).motion


# ----------------------------------------------------------------------------- processing
def baseline_correct(motion: SampledMotion, order: int = 1) -> SampledMotion:
    """Remove a polynomial baseline fitted to the **velocity**.

    The acceleration is integrated (trapezoid rule, v(0) = 0); a least-squares polynomial of
    degree ``order`` (``numpy.polynomial.Polynomial.fit``) is fitted to that velocity and its
    derivative subtracted from the acceleration. Fitting the velocity rather than the
    acceleration is the usual choice for accelerograms: a small offset in acceleration is
    invisible in its plot but makes the velocity drift linearly, and that drift is what
    the fit sees. ``order=1`` removes a constant acceleration offset; ``order=2`` a linear
    one. The scale factor and time step are kept; values stay in m/s^2.
    """
    if int(order) != order or order < 1:
        raise ArchdemInputError(f"baseline order must be an integer >= 1, got {order!r}")
    # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
    from scipy.integrate import cumulative_trapezoid

    a = motion.values
    t = motion.times
    v = cumulative_trapezoid(a, t, initial=0.0)
    p = Polynomial.fit(t, v, int(order))
    corrected = a - p.deriv()(t)
    return replace(motion, values=corrected, source=f"{motion.source}; baseline order {int(order)}".lstrip("; "))


def resample(motion: SampledMotion, dt: float) -> SampledMotion:
    """The motion on a new time step ``dt`` [s], same start, not longer than the original.

    * ``dt <= motion.dt`` (the usual case: the simulator step is finer than the record):
      linear interpolation, i.e. exactly the signal :meth:`SampledMotion.acceleration` already
      represents. The PGA is preserved exactly when ``motion.dt / dt`` is an integer, and
      otherwise drops by at most ``max|a[k+1]-a[k]| * dt / (2 motion.dt)``.
    * ``dt > motion.dt``: ``scipy.signal.resample_poly`` with the ratio written as a fraction
      (denominator <= 1000), whose anti-aliasing filter removes content above the new
      Nyquist frequency; peaks are smoothed by that filter, so the PGA is not preserved.
    """
    if not (isinstance(dt, (int, float, np.floating)) and math.isfinite(dt) and dt > 0):
        raise ArchdemInputError(f"resampling step must be positive, got {dt!r}")
    dt = float(dt)
    if dt <= motion.dt * (1 + 1e-12):
        n = int(math.floor(motion.duration / dt * (1 + 1e-12))) + 1
        t = dt * np.arange(n)
        values = np.interp(t, motion.times, motion.values)
        how = "linear"
    else:
        # deferred: `archdem --help` imports this module, not these (docs/architecture.md#imports)
        from scipy.signal import resample_poly

        ratio = motion.dt / dt
        frac = Fraction(ratio).limit_denominator(1000)
        if frac.numerator == 0 or abs(float(frac) - ratio) > 1e-9 * ratio:
            raise ArchdemInputError(f"cannot downsample from dt={motion.dt:g} to {dt:g} s: ratio is not a simple fraction")
        values = resample_poly(motion.values, frac.numerator, frac.denominator)
        how = f"resample_poly {frac.numerator}/{frac.denominator}"
    if len(values) < 2:
        raise ArchdemInputError(f"resampling step {dt:g} s leaves fewer than 2 samples of a {motion.duration:g} s record")
    return replace(motion, values=np.asarray(values, dtype=float), dt=dt,
                   source=f"{motion.source}; resampled dt={dt:g} s ({how})".lstrip("; "))


def with_zero_tail(motion: SampledMotion, seconds: float) -> SampledMotion:
    """The motion followed by ``seconds`` of zero acceleration (rounded up to whole steps)."""
    if not (isinstance(seconds, (int, float, np.floating)) and math.isfinite(seconds) and seconds >= 0):
        raise ArchdemInputError(f"zero tail must be a non-negative number of seconds, got {seconds!r}")
    n = int(math.ceil(seconds / motion.dt - 1e-9))
    if n == 0:
        return motion
    return replace(motion, values=np.concatenate([motion.values, np.zeros(n)]))


def ground_motion(sine: float | None = None, amplitude: float | None = None, record: str | Path | None = None,
                  units: str | None = None, baseline: bool = False, scale: float | None = None,
                  pga: float | None = None) -> GroundMotion:
    """The ground motion of ``archdem shake`` and ``archdem rock``, in the command line's units:
    a one-cycle sine pulse of ``sine`` [Hz] and ``amplitude`` [g] (:class:`SinePulse`, zero phase),
    or the accelerogram ``record`` (any supported format; ``units`` if the file does not say),
    optionally baseline-corrected, times ``scale``, or scaled to ``pga`` [g]."""
    def positive(name: str, v: float | None) -> None:
        if v is not None and not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ArchdemInputError(f"{name} must be a positive number, got {v}")

    if (sine is None) == (record is None):
        raise ArchdemInputError("give exactly one input: --sine FREQ --amplitude A_G, or --record FILE")
    if sine is not None:
        positive("--sine", sine)
        if amplitude is None:
            raise ArchdemInputError("--sine needs --amplitude A_G (in g)")
        positive("--amplitude", amplitude)
        if amplitude * G < MIN_PEAK_ACCELERATION:  # the floor of a record's peak holds for a sine too
            raise ArchdemInputError(f"--amplitude {amplitude:g} g is below {MIN_PEAK_ACCELERATION / G:g} g, an "
                                    "accelerometer's resolution: it moves nothing")
        given = [n for n, v in (("--scale", scale), ("--pga", pga), ("--units", units), ("--baseline", baseline or None))
                 if v is not None]
        if given:  # each would do nothing to a sine
            raise ArchdemInputError(f"{'/'.join(given)} {'goes' if len(given) == 1 else 'go'} with --record, not a sine")
        return SinePulse(amplitude * G, sine)
    if amplitude is not None:
        raise ArchdemInputError("--amplitude goes with --sine; scale a record with --scale or --pga")
    if scale is not None and pga is not None:
        raise ArchdemInputError("give --scale or --pga, not both")
    m = read_record(record, units=units)
    if baseline:
        m = baseline_correct(m)
    if scale is not None:
        if not math.isfinite(scale) or scale == 0:
            raise ArchdemInputError(f"--scale must be a non-zero number, got {scale}")
        m = m.scaled(scale)
    if pga is not None:
        positive("--pga", pga)
        m = m.to_pga(pga * G)
    return m


#: Records shipped inside the package (``analytic/motions/data/``, provenance in its README), so an
#: example runs from any folder; the full set stays with the test data.
EXAMPLE_RECORDS = ("RSN77_SFERN_PUL164.AT2",)
_EXAMPLE_DIR = Path(__file__).resolve().parent / "data"


def example_record(name: str = EXAMPLE_RECORDS[0]) -> Path:
    """The path of a record shipped with archdem: by default ``RSN77_SFERN_PUL164.AT2`` (San Fernando
    1971, Pacoima Dam 164 deg, PEER NGA-West2 AT2 in g, dt 0.01 s, PGA 1.219 g)."""
    if name not in EXAMPLE_RECORDS:
        raise ArchdemInputError(f"no shipped record {name!r}; shipped: {', '.join(EXAMPLE_RECORDS)}")
    return _EXAMPLE_DIR / name
