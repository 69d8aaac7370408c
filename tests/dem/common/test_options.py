"""The option table reads an option's help from the library field it sets: the text is declared once,
in the field's metadata, and every command that takes the option shows it."""
import argparse
import dataclasses

import pytest

from dem.common.options import OPTIONS, add_options
from dem.core.settings import Settings

BOUND = [o for o in OPTIONS if not isinstance(o.help, str)]


def _field(o):
    cls, name = o.help
    return next(f for f in dataclasses.fields(cls) if f.name == name)


def test_the_arch_and_physics_options_take_their_help_from_the_library():
    assert {o.dest for o in BOUND} >= {"id", "width", "voussoirs", "density", "contact", "geometry", "block", "mu_joint",
                                       "mu_base", "planar", "dt", "engine", "contact_law", "kn", "youngs",
                                       "damping_beta", "damping_xi", "solver_iterations"}
    for o in BOUND:
        assert _field(o).metadata["help"], o.dest


@pytest.mark.parametrize("o", BOUND, ids=lambda o: o.dest)
def test_every_command_shows_the_fields_help_unless_it_has_its_own(o):
    text, unit = _field(o).metadata["help"], _field(o).metadata.get("unit")
    for command in o.where:
        p = argparse.ArgumentParser()
        add_options(p, command, o.dest)
        shown = next(a.help for a in p._actions if a.dest == o.dest)
        if "help" not in o.per.get(command, {}):
            assert shown.startswith(text), (command, shown)
        if unit:
            assert f"[{unit}]" in shown, (command, shown)


def test_a_changed_field_help_changes_every_command(monkeypatch):
    f = next(f for f in dataclasses.fields(Settings) if f.name == "kn")
    monkeypatch.setattr(f, "metadata", {**f.metadata, "help": "springs"})
    p = argparse.ArgumentParser()
    add_options(p, "shake", "kn")
    assert next(a.help for a in p._actions if a.dest == "kn") == "springs [Pa/m]"


def test_the_default_said_is_the_commands_else_the_librarys():
    def helps(command):
        p = argparse.ArgumentParser()
        add_options(p, command, "engine", "damping_beta", "planar")
        return {a.dest: a.help for a in p._actions}

    assert helps("shake")["engine"].endswith("(default mujoco)")
    assert helps("tilt")["engine"].endswith("(default pybullet)")
    assert helps("tilt")["damping_beta"].endswith("[s] (default 0)")  # the command's None: Settings' 0
    assert "default" not in helps("shake")["planar"]  # a flag says none
