#!/usr/bin/env python3
"""Executes one notebook of examples/notebooks/ from top to bottom, as CTest does (notebook_NAME).

    python3 examples/notebooks/run_notebook.py NOTEBOOK.ipynb [--out EXECUTED.ipynb]

The notebook runs with nbclient in a Python 3 kernel (ipykernel), in a temporary folder of its own,
so that the files it writes (frames, GIFs, results) never land in the source tree. POLYPLAN_DATA
defaults to the repository's data/ beside this script. Exit status: 0 when every cell ran, 1 when a
cell raised (the cell and its error are printed) or the stored notebook holds outputs (the
repository keeps notebooks without them), 2 for bad arguments, 77 when nbclient, nbformat or
ipykernel is not importable or the notebook's metadata "polyplan": {"requires": [NAME, ...]} names
what polyplan does not have yet (CTest's SKIP_RETURN_CODE: skipped, not failed).
"""
import argparse
import os
import re
import sys
import tempfile
import time

SKIP = 77


def plain(text):
    """text without the terminal colours IPython puts in its tracebacks."""
    return re.sub(r"\x1b\[[0-9;]*m", "", text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("notebook", help="the .ipynb file to execute")
    parser.add_argument("--out", help="also write the executed notebook, with its outputs, here")
    parser.add_argument("--timeout", type=int, default=300, help="seconds per cell (default 300)")
    parser.add_argument("--allow-outputs", action="store_true",
                        help="run a notebook even when it was stored with outputs")
    args = parser.parse_args()

    try:
        import ipykernel  # noqa: F401 (the kernel nbclient starts)
        import nbclient
        import nbformat
    except ImportError as e:
        print(f"skipped: {e.name} is not importable (Debian: apt-get install python3-nbclient "
              "python3-nbformat python3-ipykernel)")
        return SKIP

    path = os.path.abspath(args.notebook)
    if not os.path.isfile(path):
        print(f"{args.notebook}: no such notebook", file=sys.stderr)
        return 2
    nb = nbformat.read(path, as_version=4)
    name = os.path.basename(path)

    stored = [i for i, cell in enumerate(nb.cells)
              if cell.cell_type == "code" and (cell.get("outputs") or cell.get("execution_count") is not None)]
    if stored and not args.allow_outputs:
        print(f"{name}: cells {stored} were stored with outputs or execution counts; clear them "
              "(Jupyter: Edit > Clear All Outputs, or jupyter nbconvert --clear-output --inplace)")
        return 1

    # A notebook written ahead of an API names it ("metadata": {"polyplan": {"requires": ["Experiment"]}}):
    # skipped while the module lacks it; it runs, and must pass, from the day the module has it.
    required = nb.metadata.get("polyplan", {}).get("requires", [])
    if required:
        try:
            import polyplan
        except ImportError:
            polyplan = None  # the notebook's first cell says why, as a failure
        missing = [n for n in required if polyplan is not None and not hasattr(polyplan, n)]
        if missing:
            print(f"skipped: {name} needs polyplan.{', polyplan.'.join(missing)}, which this build does not have")
            return SKIP

    # The kernel starts in the temporary folder: a relative PYTHONPATH (PYTHONPATH=build/python) is
    # made absolute, as this process reads it.
    if os.environ.get("PYTHONPATH"):
        os.environ["PYTHONPATH"] = os.pathsep.join(
            os.path.abspath(p) if p else p for p in os.environ["PYTHONPATH"].split(os.pathsep))
    here = os.path.dirname(os.path.abspath(__file__))
    os.environ.setdefault("POLYPLAN_DATA", os.path.normpath(os.path.join(here, "..", "..", "data")))
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the kernel's debugger: no frozen-modules warning

    with tempfile.TemporaryDirectory(prefix=f"notebook_{os.path.splitext(name)[0]}_") as work:
        client = nbclient.NotebookClient(nb, timeout=args.timeout, kernel_name="python3",
                                         resources={"metadata": {"path": work}})
        started = time.monotonic()
        try:
            client.execute()
            failed = None
        except nbclient.exceptions.CellExecutionError as e:
            failed = e
        seconds = time.monotonic() - started
        written = sorted(os.listdir(work))

    if args.out:
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        nbformat.write(nb, args.out)

    code_cells = [i for i, cell in enumerate(nb.cells) if cell.cell_type == "code"]
    if failed is not None:
        print(f"{name}: FAILED after {seconds:.1f} s")
        errors = [(i, o) for i in code_cells for o in nb.cells[i].get("outputs", []) if o.get("output_type") == "error"]
        if not errors:  # no cell holds the error (the kernel died, say): nbclient's message
            print(plain(str(failed)))
            return 1
        index, error = errors[0]
        print(f"--- cell {index} (code cell {code_cells.index(index) + 1} of {len(code_cells)}) ---")
        print(nb.cells[index].source)
        print("--- its error ---")
        print(plain("\n".join(error.get("traceback", [])) or f"{error.get('ename')}: {error.get('evalue')}"))
        return 1
    print(f"{name}: {len(code_cells)} code cells ran in {seconds:.1f} s; it wrote {written or 'no files'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
