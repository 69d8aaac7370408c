"""The shape of the house: layers point down only, and so do the sub-packages inside ``dem``; library
code never imports the command line; no import cycles; comments stay short and cite only documents of
the repository (docs/architecture.md)."""
from __future__ import annotations

import ast
import io
import re
import tokenize
from pathlib import Path

import pytest

from dem.experiments.registry import DECLARED

ROOT = Path(__file__).resolve().parents[1]
LAYERS = ("foundation", "specimens", "analytic", "dem")  # lowest first: a module may import its own layer or lower ones
MAX_COMMENT_BLOCK = 8  # lines; longer explanations belong in docs/
# the experiment folders are floors in the registry's order, so that a new experiment is its folder plus
# the registry's line (docs/architecture.md#the-experiment-contract)
EXPERIMENT_FLOORS = tuple(m.rpartition(".")[0] for m in DECLARED)
# the floors of analytic and dem, lowest first: a module imports its own sub-package or an earlier one
# (docs/architecture.md); the package tops, with their docstrings and public names, sit above their floors
SUBPACKAGES = (
    "analytic.search", "analytic.motions", "analytic.limit", "analytic.rocking", "analytic.compliant",
    "analytic.codes", "analytic",
    "dem.core", "dem.studies", "dem.common", "dem.experiments.contract",
    *EXPERIMENT_FLOORS, "dem.experiments.registry",
    "dem.campaign", "dem.cli",
    "dem.experiments", "dem",
)


def _modules() -> dict[str, Path]:
    mods = {}
    for pkg in LAYERS:
        for f in sorted((ROOT / pkg).rglob("*.py")):
            parts = list(f.relative_to(ROOT).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            mods[".".join(parts)] = f
    return mods


def import_graph() -> dict[str, set[str]]:
    """Module -> the project modules it imports, at module level or inside functions."""
    mods = _modules()

    def resolve(name: str) -> str | None:
        while name and name not in mods:
            name = name.rpartition(".")[0]
        return name or None

    edges: dict[str, set[str]] = {m: set() for m in mods}
    for m, f in mods.items():
        pkg = m if f.name == "__init__.py" else m.rpartition(".")[0]
        for node in ast.walk(ast.parse(f.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    p = pkg.split(".")[: len(pkg.split(".")) - node.level + 1]
                    base = ".".join(p + ([base] if base else []))
                targets = [base] + [f"{base}.{a.name}" for a in node.names]
            else:
                continue
            for t in targets:
                r = resolve(t)
                if r and r != m:
                    edges[m].add(r)
    return edges


def _is_package_link(a: str, b: str) -> bool:
    """A package's ``__init__`` re-exporting its own submodules (or a submodule importing its package)."""
    return a.startswith(b + ".") or b.startswith(a + ".")


def cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan), package-to-own-child links left out."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if _is_package_link(v, w):
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in edges:
        if v not in index:
            visit(v)
    return out


def subpackage_of(module: str) -> str | None:
    """The declared sub-package ``module`` belongs to (the longest that prefixes it), or None."""
    hits = [s for s in SUBPACKAGES if module == s or module.startswith(s + ".")]
    return max(hits, key=len) if hits else None


def subpackage_graph(edges: dict[str, set[str]]) -> dict[str, set[str]]:
    """Sub-package -> the other sub-packages its modules import (modules of analytic and dem)."""
    out: dict[str, set[str]] = {}
    for a, targets in edges.items():
        sa = subpackage_of(a)
        if sa is None:
            continue
        out.setdefault(sa, set())
        for b in targets:
            sb = subpackage_of(b)
            if sb is not None and sb != sa:
                out[sa].add(sb)
                out.setdefault(sb, set())
    return out


def later_imports(edges: dict[str, set[str]]) -> list[str]:
    """Imports from a sub-package into an earlier one of SUBPACKAGES, as "a -> b" (module names)."""
    rank = {s: i for i, s in enumerate(SUBPACKAGES)}
    return sorted(f"{a} -> {b}" for a in edges for b in edges[a]
                  if subpackage_of(a) and subpackage_of(b) and rank[subpackage_of(b)] > rank[subpackage_of(a)])


def test_a_floor_of_analytic_importing_a_later_one_fails():
    edges = {"analytic.limit.two_bar": {"analytic.rocking.linkage"}, "analytic.rocking.linkage": set()}
    assert later_imports(edges) == ["analytic.limit.two_bar -> analytic.rocking.linkage"]


def test_the_graph_sees_imports_inside_functions():
    # the campaign runner imports the report inside a function: the graph must see it
    assert "dem.campaign.report" in import_graph()["dem.campaign.runner"]


def test_layers_point_down_only():
    edges = import_graph()
    layer = lambda m: LAYERS.index(m.split(".")[0])  # noqa: E731
    upward = sorted(f"{a} -> {b}" for a in edges for b in edges[a] if layer(b) > layer(a))
    assert upward == []


def is_command_line(module: str) -> bool:
    """The command line: the program (dem.cli), the sub-command modules (``NAME_cmd``, beside their
    experiments) and their shared options (dem.common.options)."""
    return (module == "dem.cli" or module.startswith("dem.cli.") or module.rpartition(".")[2].endswith("_cmd")
            or module == "dem.common.options")


def test_library_code_never_imports_the_cli():
    edges = import_graph()
    bad = sorted(f"{a} -> {b}" for a in edges for b in edges[a] if is_command_line(b) and not is_command_line(a))
    assert bad == []


def test_every_module_of_analytic_and_dem_sits_in_a_declared_subpackage():
    assert [m for m in import_graph() if m.startswith(("analytic", "dem")) and subpackage_of(m) is None] == []
    assert all((ROOT / s.replace(".", "/") / "__init__.py").is_file() or (ROOT / (s.replace(".", "/") + ".py")).is_file()
               for s in SUBPACKAGES)


def test_subpackages_import_only_earlier_ones():
    assert later_imports(import_graph()) == []


def test_no_cycles_between_subpackages():
    assert cycles(subpackage_graph(import_graph())) == []


def test_a_planted_cycle_between_subpackages_fails():
    """Two sub-packages importing each other (core -> campaign is the later import) and a longer loop
    through three experiments are both found, as module edges and as sub-package cycles."""
    edges = {
        "dem.core.model": {"dem.campaign.runner"}, "dem.campaign.runner": {"dem.core.model"},
        "dem.experiments.tilt.run": {"dem.experiments.shake.run"},
        "dem.experiments.shake.run": {"dem.experiments.fragility.run"},
        "dem.experiments.fragility.run": {"dem.experiments.tilt.case"}, "dem.experiments.tilt.case": set(),
    }
    assert later_imports(edges) == ["dem.core.model -> dem.campaign.runner",
                                    "dem.experiments.shake.run -> dem.experiments.fragility.run",
                                    "dem.experiments.tilt.run -> dem.experiments.shake.run"]
    assert sorted(cycles(subpackage_graph(edges))) == [
        ["dem.campaign", "dem.core"],
        ["dem.experiments.fragility", "dem.experiments.shake", "dem.experiments.tilt"],
    ]
    # within a sub-package modules may import each other in any order, as long as there is no cycle
    assert later_imports({"dem.experiments.tilt.step_tilt": {"dem.experiments.tilt.run"}}) == []


EXPERIMENTS = "dem.experiments."


def experiment_of(module: str) -> str | None:
    """The experiment folder ``module`` belongs to (``dem.experiments.NAME``, a folder), or None (modules of
    ``dem.experiments`` beside the folders are no experiment)."""
    top = ".".join(module.split(".")[:3])
    return top if module.startswith(EXPERIMENTS) and (ROOT / top.replace(".", "/")).is_dir() else None


def foreign_submodule_imports(edges: dict[str, set[str]]) -> list[str]:
    """Imports by a module of one experiment folder of a submodule of another, as "a -> b": another
    experiment is used only through its package top, its contract (docs/architecture.md)."""
    return sorted(f"{a} -> {b}" for a in edges for b in edges[a]
                  if experiment_of(a) and experiment_of(b) and experiment_of(a) != experiment_of(b)
                  and b != experiment_of(b))


def test_experiments_import_each_other_only_through_their_package_top():
    assert foreign_submodule_imports(import_graph()) == []


def test_a_planted_import_of_another_experiments_submodule_fails():
    """A submodule of another experiment is found (at any depth); its package top, the experiment's
    own modules and modules outside the experiment folders (the campaign, a registry of them) are not."""
    edges = {
        "dem.experiments.fragility.run": {"dem.experiments.shake.run", "dem.experiments.tilt",
                                          "dem.experiments.fragility.file", "dem.common.arch"},
        "dem.experiments.fragility.figure": {"dem.experiments.shake.figure"},
        "dem.experiments.record": {"dem.experiments.shake.thresholds"},
        "dem.campaign.runner": {"dem.experiments.shake.step_shake"},
        "dem.experiments.registry": {"dem.experiments.tilt.experiment"},
    }
    assert foreign_submodule_imports(edges) == ["dem.experiments.fragility.figure -> dem.experiments.shake.figure",
                                                "dem.experiments.fragility.run -> dem.experiments.shake.run",
                                                "dem.experiments.record -> dem.experiments.shake.thresholds"]


def test_an_experiments_package_top_is_light():
    # its contract is re-exported lazily: importing the tops loads none of their modules
    import subprocess
    import sys

    tops = sorted(s for s in SUBPACKAGES if s.startswith(EXPERIMENTS))
    code = (f"import importlib, sys\nfor t in {tops!r}:\n    importlib.import_module(t)\n"
            "print(' '.join(sorted(m for m in sys.modules if m.startswith('dem.experiments.') and m.count('.') > 2)))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True).stdout
    assert out.split() == []


def test_the_graph_resolves_a_name_of_a_package_top_to_the_top():
    # `from dem.experiments.shake import threshold` names the package top; `... import thresholds`, a submodule
    edges = import_graph()
    assert "dem.experiments.shake" in edges["dem.experiments.record.run"]
    assert "dem.experiments.shake.run" not in edges["dem.experiments.record.run"]


def test_no_import_cycles():
    assert cycles(import_graph()) == []


ENGINES = "dem.core.engines"


def backend_of(module: str) -> str | None:
    """The engine a module of ``dem.core.engines`` belongs to (its name starts with the engine's:
    ``lmgc90_worker`` is LMGC90's), None for the engine-neutral ones (base, inputs, options)."""
    from dem.core.engines import available_engines

    if not module.startswith(ENGINES + "."):
        return None
    leaf = module[len(ENGINES) + 1:].split(".")[0]
    return next((e for e in available_engines() if leaf.startswith(e)), None)


def cross_backend_imports(edges: dict[str, set[str]]) -> list[str]:
    """Imports from one engine's backend modules into another engine's, as "a -> b" (module names)."""
    return sorted(f"{a} -> {b}" for a in edges for b in edges[a]
                  if backend_of(a) and backend_of(b) and backend_of(a) != backend_of(b))


def test_no_engine_imports_another():
    # what two engines share sits in an engine-neutral module (dem.core.model, dem.core.engines.base, inputs, options)
    edges = import_graph()
    assert {backend_of(m) for m in edges} - {None} == {"pybullet", "mujoco", "lmgc90"}
    assert cross_backend_imports(edges) == []


def test_a_planted_import_between_engines_fails():
    edges = {"dem.core.engines.lmgc90_engine": {"dem.core.engines.pybullet_engine", "dem.core.engines.base"},
             "dem.core.engines.lmgc90_worker": {"dem.core.engines.lmgc90_engine"},
             "dem.core.engines.mujoco_engine": {"dem.core.engines.options", "dem.core.model"},
             "dem.core.engines.pybullet_engine": {"dem.core.engines.mujoco_engine"}}
    assert cross_backend_imports(edges) == ["dem.core.engines.lmgc90_engine -> dem.core.engines.pybullet_engine",
                                            "dem.core.engines.pybullet_engine -> dem.core.engines.mujoco_engine"]


def test_cycle_detection_finds_a_cycle():
    assert cycles({"a.x": {"a.y"}, "a.y": {"a.z"}, "a.z": {"a.x"}, "a.w": set()}) == [["a.x", "a.y", "a.z"]]


def _comment_blocks(path: Path) -> list[tuple[int, int]]:
    """(first line, length) of every run of consecutive lines that carry a comment (a field list with
    a comment on every line counts as one block too)."""
    text = path.read_text(encoding="utf-8")
    lines = {tok.start[0] for tok in tokenize.generate_tokens(io.StringIO(text).readline) if tok.type == tokenize.COMMENT}
    blocks, start, run = [], 0, 0
    for i in range(1, len(text.splitlines()) + 2):
        if i in lines:
            start, run = (i, 1) if run == 0 else (start, run + 1)
        elif run:
            blocks.append((start, run))
            run = 0
    return blocks


@pytest.mark.parametrize("pkg", LAYERS)
def test_comments_are_short(pkg):
    long = [f"{f.relative_to(ROOT)}:{s} ({n} lines)" for f in sorted((ROOT / pkg).rglob("*.py"))
            for s, n in _comment_blocks(f) if n > MAX_COMMENT_BLOCK]
    assert long == []


EXTERNAL = re.compile(r"\bspec(?:ification)?\s*(?:0\d|§)|\bspec §|https?://", re.I)


@pytest.mark.parametrize("pkg", LAYERS + ("benchmarks", "tests"))
def test_code_cites_only_documents_of_the_repository(pkg):
    bad = [f"{f.relative_to(ROOT)}:{k}" for f in sorted((ROOT / pkg).rglob("*.py")) if f != Path(__file__)
           for k, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1) if EXTERNAL.search(line)]
    assert bad == []


def test_cited_docs_exist():
    cited = set()
    for pkg in LAYERS + ("benchmarks",):
        for f in (ROOT / pkg).rglob("*.py"):
            cited |= set(re.findall(r"docs/[\w./-]+\.md", f.read_text(encoding="utf-8")))
    missing = sorted(c for c in cited if not (ROOT / c).is_file())
    assert missing == []


def test_public_names_exist():
    import importlib
    import pkgutil

    missing = []
    for pkg in LAYERS:
        top = importlib.import_module(pkg)
        names = [pkg] + [m.name for m in pkgutil.walk_packages(top.__path__, pkg + ".") if not m.name.endswith("__main__")]
        for name in names:
            mod = importlib.import_module(name)
            missing += [f"{name}.{a}" for a in getattr(mod, "__all__", ()) if not hasattr(mod, a)]
    assert missing == []
    assert {"tilt", "shake", "threshold", "ground_motion", "Settings"} <= set(importlib.import_module("dem").__all__)


# heavy libraries `archdem --help` must not load: each costs a second or more of start-up (trimesh alone
# 0.45 s), and the help needs none of them
HELP_FORBIDDEN = ("scipy", "trimesh", "h5py", "matplotlib", "pybullet", "mujoco", "ezdxf", "dask")


@pytest.mark.slow
def test_help_imports_no_heavy_library():
    import subprocess
    import sys

    code = ("import sys\nfrom dem.cli import main\ntry:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
            f"print('HEAVY:' + ' '.join(sorted({{m.split('.')[0] for m in sys.modules}} & set({HELP_FORBIDDEN!r}))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True).stdout
    heavy = out.rsplit("HEAVY:", 1)[1].split()
    assert heavy == [], f"archdem --help imports {', '.join(heavy)}"
