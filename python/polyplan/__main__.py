"""python3 -m polyplan COMMAND ...: the polyplan program's commands, from the installed module.

A command of COMMANDS runs here, in Python; every other is the program's, which replaces this
process (its output and exit code are the program's own).
"""
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))



def _benchmark(args):
    from .cluster import benchmark_command
    return benchmark_command(args)


# Python-side commands: name -> function(arguments after the name) returning the exit code.
COMMANDS = {"benchmark": _benchmark}


def program():
    """The polyplan program: the package's own (pip install . and scripts/python.sh put it in
    _bin/), else $POLYPLAN_CLI (a path or a name on PATH), else the one built beside this build
    tree's package (python/CMakeLists.txt writes its path in _cli_path); None when there is none."""
    installed = os.path.join(HERE, "_bin", "polyplan")
    if os.access(installed, os.X_OK):
        return installed
    if os.environ.get("POLYPLAN_CLI"):
        return shutil.which(os.environ["POLYPLAN_CLI"])
    try:
        with open(os.path.join(HERE, "_cli_path")) as f:
            return shutil.which(f.read().strip())
    except OSError:
        return None


def main(args=None):
    args = sys.argv[1:] if args is None else args
    if args and args[0] in COMMANDS:
        return COMMANDS[args[0]](args[1:])
    path = program()
    if path is None:
        print(f"error: no polyplan program: none in {HERE}/_bin, POLYPLAN_CLI unset or not a program,"
              " and not a build tree", file=sys.stderr)
        return 2
    # The program's usage line names its argv[0]: say how it was run.
    name = os.path.basename(sys.executable or "python3") + " -m polyplan"
    sys.stdout.flush()
    try:
        os.execv(path, [name, *args])
    except OSError as e:
        print(f"error: cannot run {path}: {e.strerror}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
