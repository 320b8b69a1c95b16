"""The contract every public function of cagd_ref keeps (DESIGN.md, "Conventions of cagd_ref").

For every name in every module's ``__all__`` a valid call is registered in
`tests/ref/calls/<module>.py`; from it this file checks, for all of them at once:
the call works; NaN or inf in any real-valued argument raises a ValueError that
names the argument; no argument is modified; a scalar curve parameter gives one
result (d,), an array of k parameters (k, d). A public function without a
registered call fails here, so a new module cannot skip the contract.
"""

from __future__ import annotations

import copy
import importlib
import inspect
import numbers
import pkgutil

import numpy as np
import pytest

import cagd_ref

from .calls import Call

MODULES = sorted(m.name for m in pkgutil.iter_modules(cagd_ref.__path__) if not m.name.startswith("_"))


def registered(module_name: str) -> dict[str, list[Call]]:
    """The calls registered for cagd_ref.<module_name>; none when its registry is missing (which then fails)."""
    try:
        calls = importlib.import_module(f"{__package__}.calls.{module_name}").CALLS
    except ModuleNotFoundError as err:
        if err.name != f"{__package__}.calls.{module_name}":
            raise
        return {}
    return {name: value if isinstance(value, list) else [value] for name, value in calls.items()}


def public_functions(module_name: str) -> dict:
    module = importlib.import_module(f"cagd_ref.{module_name}")
    return {name: getattr(module, name) for name in module.__all__ if callable(getattr(module, name))}


CASES = [
    pytest.param(module, name, index, call, id=f"{module}.{name}" + (f"[{index}]" if index else ""))
    for module in MODULES
    for name, calls in registered(module).items()
    for index, call in enumerate(calls)
]


@pytest.mark.parametrize("module", MODULES)
def test_every_public_function_has_a_registered_call(module):
    functions = public_functions(module)
    calls = registered(module)
    assert set(functions) - set(calls) == set(), f"register a Call in tests/ref/calls/{module}.py"
    assert set(calls) - set(functions) == set(), "registered calls of names that are not in __all__"


def bound_arguments(function, call: Call) -> inspect.BoundArguments:
    return inspect.signature(function).bind(*copy.deepcopy(call.args), **copy.deepcopy(call.kwargs))


def invoke(function, bound: inspect.BoundArguments):
    return function(*bound.args, **bound.kwargs)


def is_real_valued(value) -> bool:
    """Floats and arrays or (nested) lists of numbers: the arguments NaN and inf must not slip into."""
    if isinstance(value, (bool, np.bool_)):
        return False
    if isinstance(value, numbers.Integral):
        return False
    if isinstance(value, numbers.Real):
        return True
    if isinstance(value, (list, tuple, np.ndarray)):
        try:
            array = np.asarray(value)
        except ValueError:  # ragged
            return False
        return array.size > 0 and array.dtype.kind in "iuf"
    return False


def poisoned(value, bad: float):
    """A copy of `value` with its first entry replaced by `bad` (NaN or inf)."""
    if isinstance(value, numbers.Real):
        return bad
    array = np.array(value, dtype=float)
    array.flat[0] = bad
    return array


def function_of(module: str, name: str):
    return getattr(importlib.import_module(f"cagd_ref.{module}"), name)


@pytest.mark.parametrize("module, name, index, call", CASES)
def test_the_registered_call_works_and_modifies_nothing(module, name, index, call):
    function = function_of(module, name)
    bound = bound_arguments(function, call)
    before = copy.deepcopy(bound.arguments)
    invoke(function, bound)
    for argument, old in before.items():
        new = bound.arguments[argument]
        if is_real_valued(old) or isinstance(old, np.ndarray):
            np.testing.assert_array_equal(np.asarray(new), np.asarray(old), err_msg=f"{name} modified {argument}")


@pytest.mark.parametrize("module, name, index, call", CASES)
@pytest.mark.parametrize("bad", [np.nan, np.inf], ids=["nan", "inf"])
def test_nan_and_inf_are_rejected_by_name(module, name, index, call, bad):
    if call.finite_only == ("*",):
        pytest.skip("every argument of this call accepts non-finite values")
    function = function_of(module, name)
    arguments = [a for a, v in bound_arguments(function, call).arguments.items()
                 if is_real_valued(v) and a not in call.finite_only]
    if not arguments:
        pytest.skip("no real-valued argument")
    for argument in arguments:
        bound = bound_arguments(function, call)
        bound.arguments[argument] = poisoned(bound.arguments[argument], bad)
        with pytest.raises(ValueError, match=rf"^{argument}\b"):
            invoke(function, bound)


def as_arrays(result) -> list[np.ndarray]:
    return [np.asarray(part) for part in result] if isinstance(result, tuple) else [np.asarray(result)]


@pytest.mark.parametrize("module, name, index, call", [case for case in CASES if case.values[3].parameter])
def test_a_scalar_parameter_gives_one_result_an_array_gives_one_per_value(module, name, index, call):
    function = function_of(module, name)
    bound = bound_arguments(function, call)
    t = bound.arguments[call.parameter]
    assert np.ndim(t) == 0, "register the scalar form of the parameter"
    singles = as_arrays(invoke(function, bound))
    for values in ([t, t, t], np.array([t, t]), [t]):
        bound.arguments[call.parameter] = values
        for single, many in zip(singles, as_arrays(invoke(function, bound))):
            assert many.shape == (len(values),) + single.shape
            np.testing.assert_allclose(many, np.broadcast_to(single, many.shape), rtol=1e-12, atol=1e-12)
    bound.arguments[call.parameter] = np.array([])
    for single, none in zip(singles, as_arrays(invoke(function, bound))):
        assert none.shape == (0,) + single.shape
