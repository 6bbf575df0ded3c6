"""python3 -m polyplan runs the polyplan program: its help lists the program's commands, a plan
prints what the program prints, and without a program it says so in one line."""
import os
import re
import subprocess
import sys

import polyplan.__main__ as main_module
from conftest import data, run_cli


def module(*args):
    """python3 -m polyplan ARGS, left to find the program itself (POLYPLAN_CLI unset: in a build
    tree, the path python/CMakeLists.txt wrote in _cli_path)."""
    env = {k: v for k, v in os.environ.items() if k != "POLYPLAN_CLI"}
    return subprocess.run([sys.executable, "-m", "polyplan", *args], capture_output=True, text=True,
                          timeout=600, env=env)


def test_help_lists_the_commands():
    done = module("--help")
    assert done.returncode == 0, done.stderr
    assert "-m polyplan [OPTIONS] SUBCOMMAND" in done.stdout  # the usage line says how it was run
    for command in ("plan", "planners", "benchmark"):
        assert re.search(rf"^ +{command} ", done.stdout, re.M), command


def test_plan_prints_what_the_program_prints():
    world = data("worlds", "seed004.json")
    ran = module("plan", world)
    code, out, _ = run_cli("plan", world)  # the program at POLYPLAN_CLI
    assert ran.returncode == code == 0, ran.stderr
    assert ran.stdout == out and "length 118.944400" in out


def test_no_program_is_one_line_and_exit_2(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(main_module, "HERE", str(tmp_path))  # no _bin/ and no _cli_path there
    monkeypatch.delenv("POLYPLAN_CLI", raising=False)
    assert main_module.main(["--help"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: no polyplan program:") and err.count("\n") == 1
