"""The stub file __init__.pyi says what the module has: the same public names, classes with the
same members, functions with the same parameters. Every public name has a docstring."""
import ast
import inspect
import os
import re

import pytest

import polyplan

STUB = os.path.join(os.path.dirname(polyplan.__file__), "__init__.pyi")
ALIASES = {"Number", "PointLike", "PathLike", "Problem"}  # the stub's own type aliases


def stub_tree():
    with open(STUB) as f:
        return ast.parse(f.read())


def stub_functions(body):
    return {n.name: n for n in body if isinstance(n, ast.FunctionDef)}


def stub_classes():
    return {n.name: n for n in stub_tree().body if isinstance(n, ast.ClassDef)}


def parameters_of_stub(f):
    a = f.args
    names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
    if a.vararg:
        names.append("*" + a.vararg.arg)
    if a.kwarg:
        names.append("**" + a.kwarg.arg)
    return [n for n in names if n not in ("self", "cls")]


def parameters_of(obj):
    """The parameter names of a Python function, or of a pybind11 one (from its signature line)."""
    try:
        signature = inspect.signature(obj)
    except (TypeError, ValueError):
        signature = None
    if signature is not None:
        out = []
        for p in signature.parameters.values():
            prefix = {p.VAR_POSITIONAL: "*", p.VAR_KEYWORD: "**"}.get(p.kind, "")
            out.append(prefix + p.name)
        return [n for n in out if n not in ("self", "cls")]
    first = obj.__doc__.splitlines()[0]
    inside = re.match(r"^\w+\((.*)\) ->", first).group(1)
    names = []
    for part in re.split(r",\s*(?![^\[]*\])", inside):
        if not part:
            continue
        name = part.split(":")[0].strip()
        names.append(name)
    return [n for n in names if n not in ("self", "cls")]


def public_members(cls):
    return {n for n in dir(cls) if not n.startswith("_")} - set(dir(tuple) if issubclass(cls, tuple) else ())


def test_the_stub_has_every_public_name():
    tree = stub_tree()
    declared = set(stub_functions(tree.body)) | set(stub_classes())
    declared |= {t.id for n in tree.body if isinstance(n, ast.Assign) for t in n.targets}
    assert declared - ALIASES == set(polyplan.__all__)
    for name in polyplan.__all__:
        assert hasattr(polyplan, name), name


@pytest.mark.parametrize("name", sorted(n for n in polyplan.__all__ if inspect.isclass(getattr(polyplan, n))))
def test_each_class_has_the_stubs_members(name):
    cls = getattr(polyplan, name)
    node = stub_classes()[name]
    if issubclass(cls, BaseException):  # InputError (a ValueError), ExperimentInterrupted (a KeyboardInterrupt)
        assert issubclass(cls, (ValueError, KeyboardInterrupt)) and node.body and not [n for n in node.body if isinstance(n, ast.FunctionDef)]
        return
    if issubclass(cls, tuple):
        fields = [n.target.id for n in node.body if isinstance(n, ast.AnnAssign)]
        assert tuple(fields) == cls._fields
        return
    declared = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
    assert declared == public_members(cls), name
    for method, f in stub_functions(node.body).items():
        member = inspect.getattr_static(cls, method)
        if isinstance(member, property) or type(member).__name__ == "property":
            assert any(isinstance(d, ast.Name) and d.id == "property" for d in f.decorator_list), f"{name}.{method} is a property"
            continue
        assert parameters_of(getattr(cls, method)) == parameters_of_stub(f), f"{name}.{method}"


@pytest.mark.parametrize("name", sorted(n for n in polyplan.__all__ if not inspect.isclass(getattr(polyplan, n))))
def test_each_function_has_the_stubs_parameters(name):
    assert parameters_of(getattr(polyplan, name)) == parameters_of_stub(stub_functions(stub_tree().body)[name])


@pytest.mark.parametrize("name", sorted(polyplan.__all__))
def test_every_name_has_a_docstring(name):
    obj = getattr(polyplan, name)
    doc = inspect.getdoc(obj) or ""
    assert len(doc) > 40, name
    if inspect.isclass(obj) and not issubclass(obj, (tuple, BaseException)):
        for member in public_members(obj):
            assert len(inspect.getdoc(getattr(obj, member)) or "") > 10, f"{name}.{member}"


def test_help_on_plan_is_useful():
    doc = inspect.getdoc(polyplan.plan)
    for word in ("World", "Arm", "planners()", "InputError", "seed"):
        assert word in doc
