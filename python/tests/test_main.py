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


def test_benchmark_runs_here_and_refuses_bad_arguments_naming_them(tmp_path):
    """benchmark is Python's (polyplan.cluster): its runs as tasks on threads (or a Dask cluster),
    each record kept as it comes; bad arguments exit 2 naming the flag."""
    experiment = tmp_path / "tiny.json"
    experiment.write_text('{"name": "tiny", "problems": [{"name": "office", "file": "%s"}], '
                          '"planners": [{"name": "rrt", "planner": "rrt"}], "seeds": [1, 2], "time_limit": 5}'
                          % data("worlds", "office.json"))
    ran = module("benchmark", str(experiment), "--threads", "2", "--out", str(tmp_path / "out"))
    assert ran.returncode == 0, ran.stderr
    assert "tiny: 2 runs, 2 solved" in ran.stdout and "runs: 2/2, 2 solved, 0 failed" in ran.stderr
    assert len((tmp_path / "out" / "runs.jsonl").read_text().splitlines()) == 3
    for args, message in ((["--threads", "-1"], "argument --threads: -1: expected a whole number in [0, 256]"),
                          (["--seeds", "0"], "argument --seeds: 0: expected a whole number in [1, inf]"),
                          (["--seeds", "3"], "error: --seeds 3: the experiment has 2 seeds"),
                          (["--time-limit", "nan"], "argument --time-limit: 'nan': expected a finite number"),
                          (["--out", str(experiment)], f"error: --out {experiment}: not a folder"),
                          (["--local-cluster", "0"], "error: --local-cluster 0: expected 1 to 256 workers"),
                          (["--resume", str(tmp_path)], "runs.jsonl: cannot resume from it")):
        refused = module("benchmark", str(experiment), *args)
        assert refused.returncode == 2 and message in refused.stderr, (args, refused.stderr)
