"""The options of ``archdem fragility`` come from its spec: the defaults are the library's, the
British spelling of --realizations is an alias, the help shows the library's scatters."""
from dem.cli import build_parser
from dem.experiments.fragility.run import DEFAULT_EDGE_LOSS_SD, DEFAULT_FRICTION_COV, DEFAULT_SIZE_SD
from dem.experiments.fragility.spec import FragilityOptions


def _fragility():
    sub = build_parser()._subparsers._group_actions[0].choices
    return sub["fragility"]


def test_the_options_are_the_spec_s_with_the_library_s_defaults():
    p = _fragility()
    args = p.parse_args(["Sh02-Sd015", "--realisations", "3", "--records", "a.AT2", "b.AT2"])
    assert args.realizations == 3 and args.records == ["a.AT2", "b.AT2"]
    assert args.friction_cov == DEFAULT_FRICTION_COV == FragilityOptions.friction_cov and args.seed == 0
    assert args.edge_loss is None and args.edge_loss_sd is None and args.no_deterministic is False
    text = " ".join(p.format_help().split())
    assert f"arch: scatter of the joints' edge loss [mm] (default {DEFAULT_EDGE_LOSS_SD * 1e3:g})" in text
    assert f"block: scatter of a block's base and height [mm] (default {DEFAULT_SIZE_SD * 1e3:g})" in text
    assert "arch: mean edge loss of every joint [mm] (default 0)" in text
