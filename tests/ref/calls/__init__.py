"""The registry of valid calls that the contract test (`tests/ref/test_contract.py`) makes on cagd_ref.

One module here per module of cagd_ref, with the same name, defining
``CALLS = {function_name: Call(...) or [Call(...), ...]}`` for every name in that
module's ``__all__``. A new chapter registers the calls of its module and gets
every check of the contract for free.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Call:
    """One valid call of a public function, and what the contract test may do with it.

    args, kwargs: the call. Every real-valued argument (a float, or an array or
    list of numbers) is poisoned in turn with NaN and with inf, and the call must
    then raise a ValueError whose message starts with that argument's name; ints
    and bools (counts, indices, flags) are left alone.
    parameter: the name of the argument that is the curve parameter t, if any: a
    number must give one result of shape (d,), k numbers (k, d), row by row the same.
    finite_only: arguments that accept NaN or inf by design (listed with the reason
    in a comment), left out of the poisoning; "*" leaves them all out.
    """

    args: tuple = ()
    kwargs: dict = field(default_factory=dict)
    parameter: str | None = None
    finite_only: tuple[str, ...] = ()
