"""The type stubs (lcmtf/__init__.pyi) declare exactly what the package has: its names, each
class's members, and every function's parameters with their defaults."""

import ast
import inspect
import pathlib
import re

import pytest

import lcmtf

STUB = ast.parse((pathlib.Path(lcmtf.__file__).parent / "__init__.pyi").read_text())
STUB_CLASSES = {node.name: node for node in STUB.body if isinstance(node, ast.ClassDef)}
DECLARED_DUNDERS = {"__init__", "__len__", "__enter__", "__exit__", "__eq__"}
SLOT = type(object.__init__)  # what pybind11 leaves as __init__ in a class Python cannot make


def stub_names():
    names = set(STUB_CLASSES)
    for node in STUB.body:
        if isinstance(node, ast.FunctionDef):
            names.add(node.name)
        elif isinstance(node, ast.ImportFrom):
            names.update(alias.asname for alias in node.names if alias.asname == alias.name)
    return names


def split_parameters(text):
    """`text` split at the commas that are not inside brackets."""
    parts, depth, current = [], 0, ""
    for character in text:
        depth += character in "([{"
        depth -= character in ")]}"
        if character == "," and depth == 0:
            parts.append(current.strip())
            current = ""
        else:
            current += character
    return parts + ([current.strip()] if current.strip() else [])


def default_of(text):
    try:
        return ast.literal_eval(text)
    except ValueError:
        return text


def runtime_signatures(function):
    """Each form of `function` as [(name, default)], from pybind11's docstring or inspect."""
    name = function.__name__
    if inspect.isfunction(function):
        form = []
        for p in list(inspect.signature(function).parameters.values())[1:]:
            if p.kind is p.KEYWORD_ONLY and ("*", ...) not in form:
                form.append(("*", ...))  # as pybind11 writes the marker
            form.append((p.name, p.default if p.default is not p.empty else ...))
        return [form]
    forms = []
    for match in re.finditer(r"^(?:\d+\. )?" + name + r"\((.*)\) -> ", function.__doc__, re.M):
        form = []
        for parameter in split_parameters(match.group(1)):
            if parameter.startswith("self"):
                continue
            head, _, default = parameter.partition(" = ")
            form.append((head.split(":")[0], default_of(default) if default else ...))
        forms.append(form)
    return [form for form in forms if form != [("*args", ...), ("**kwargs", ...)]]


def stub_signatures(name, body):
    """Each form of `name` in the stub as [(name, default)]; overloads that differ only in
    their types (Literal[True] and Literal[False]) are one form."""
    forms = {}
    for node in body:
        if isinstance(node, ast.FunctionDef) and node.name == name:
            arguments = node.args
            positional = [a.arg for a in arguments.args if a.arg != "self"]
            defaults = [...] * (len(positional) - len(arguments.defaults)) + [
                ast.literal_eval(d) for d in arguments.defaults]
            form = list(zip(positional, defaults))
            if arguments.kwonlyargs:
                form.append(("*", ...))
                form += [(a.arg, ast.literal_eval(d) if d is not None else ...)
                         for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults)]
            names = tuple(parameter for parameter, _ in form)
            known = forms.setdefault(names, form)
            forms[names] = [(p, d if d is not ... else k) for (p, d), (_, k) in zip(form, known)]
    return list(forms.values())


def stub_members(node):
    members = set()
    for item in node.body:
        if isinstance(item, ast.FunctionDef):
            members.add(item.name)
        elif isinstance(item, ast.AnnAssign):
            members.add(item.target.id)
    return members


def test_the_stub_declares_every_public_name_and_nothing_else():
    assert stub_names() == set(lcmtf.__all__)


@pytest.mark.parametrize("name", sorted(n for n in STUB_CLASSES if not n.endswith("Exception")))
def test_each_class_has_the_members_its_stub_declares(name):
    runtime = getattr(lcmtf, name)
    own = [k for k in runtime.__mro__ if k.__name__ not in ("object", "pybind11_object")]
    public = {n for k in own for n, v in vars(k).items()
              if not n.startswith("_") or n in DECLARED_DUNDERS and not isinstance(v, SLOT)}
    assert stub_members(STUB_CLASSES[name]) == public


@pytest.mark.parametrize("name", sorted(n for n in STUB_CLASSES if n.endswith("Exception")))
def test_each_exception_has_the_base_its_stub_declares(name):
    bases = [base.id for base in STUB_CLASSES[name].bases]
    assert [base.__name__ for base in getattr(lcmtf, name).__bases__] == bases


def functions():
    for node in STUB.body:
        if isinstance(node, ast.FunctionDef):
            yield node.name, getattr(lcmtf, node.name), STUB.body
    for class_name, node in STUB_CLASSES.items():
        for member in stub_members(node):
            runtime_class = getattr(lcmtf, class_name)
            runtime = inspect.getattr_static(runtime_class, member, None)
            if callable(runtime) and not isinstance(runtime, property) and member != "__exit__":
                yield f"{class_name}.{member}", getattr(runtime_class, member), node.body


@pytest.mark.parametrize("name, function, body", functions(),
                         ids=lambda value: value if isinstance(value, str) else "")
def test_each_function_takes_the_parameters_its_stub_declares(name, function, body):
    expected = stub_signatures(name.rpartition(".")[2], body)
    actual = runtime_signatures(function)
    assert sorted(map(str, actual)) == sorted(map(str, expected))
