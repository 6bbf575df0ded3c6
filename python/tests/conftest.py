"""What the polyplan tests share: the data folder, the program (to compare with) and its JSON."""
import json
import os
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.environ.get("POLYPLAN_DATA", os.path.join(HERE, "..", "..", "data"))
CLI = os.environ.get("POLYPLAN_CLI", "polyplan")


# What the clock decides in an experiment's record (results.json's "runs").
RECORD_TIMES = ("time", "setup_time", "first_solution_time", "improvements", "cost_at")


def clockless(record):
    """An experiment's record without what the clock decides: the same for the same seed wherever
    the run was made, when the run stops by its own rule (not by its time limit)."""
    kept = {k: v for k, v in record.items() if k not in RECORD_TIMES}
    kept["facts"] = {k: v for k, v in record["facts"].items() if "seconds" not in k}
    return kept


def data(*parts):
    return os.path.join(DATA, *parts)


def shipped(folder):
    """The JSON files of data/<folder>, sorted."""
    return sorted(f for f in os.listdir(data(folder)) if f.endswith(".json"))


def run_cli(*args):
    """(exit code, stdout, stderr) of the polyplan program."""
    done = subprocess.run([CLI, *args], capture_output=True, text=True, timeout=600)
    return done.returncode, done.stdout, done.stderr


def cli_json(*args):
    """The program's --json - output, parsed; None and its one-line error when it refused."""
    code, out, err = run_cli(*args, "--json", "-")
    if code != 0:
        return None, err.strip()
    return json.loads(out), None


@pytest.fixture
def seed004():
    import polyplan
    return polyplan.read_world(data("worlds", "seed004.json"))
