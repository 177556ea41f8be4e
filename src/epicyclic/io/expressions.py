"""A safe arithmetic parser for ratios written as expressions, e.g. ``"(24/50)*(42/30)"``.

Input files may give a stationary ratio or a stage ratio exactly, as the
sources write it (Brandenberger's ``a/b · c/d``).  The text is parsed with
:mod:`ast` and evaluated by walking a whitelist of nodes — numbers, ``+ - * /``,
``**`` with a small exponent, unary signs and parentheses.  Nothing else is
accepted: no names, calls, attributes or subscripts; ``eval`` is never used.

Examples
--------
>>> round(evaluate("(24/50)*(42/30)"), 12)
0.672
>>> evaluate("-78/30")
-2.6
"""

from __future__ import annotations

import ast
import math
import operator
import warnings

from ..errors import ModelError
from ..limits import MAX_EXPRESSION_CHARS as MAX_LENGTH
from ..limits import MAX_EXPRESSION_EXPONENT as MAX_EXPONENT

__all__ = ["ExpressionError", "evaluate", "MAX_LENGTH"]

_BINARY = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.Pow: operator.pow,
}
_UNARY = {ast.UAdd: operator.pos, ast.USub: operator.neg}
_SYMBOL = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**"}


class ExpressionError(ModelError):
    """An arithmetic expression that cannot be read or evaluated.

    Attributes
    ----------
    expression : str
        The text given.
    field : str
        Where it was given.
    """

    def __init__(self, message: str, expression: str = "", field: str = ""):
        self.expression = expression
        self.field = field
        super().__init__(message)


def evaluate(text: str, field: str = "expression") -> float:
    """Evaluate an arithmetic expression of numbers safely.

    Parameters
    ----------
    text : str
        Numbers combined with ``+ - * / **`` and parentheses, e.g.
        ``"(44/40)*(64/20)"``.  Spaces are ignored.
    field : str
        Where the expression was given; named in error messages.

    Returns
    -------
    float
        The finite value.

    Raises
    ------
    ExpressionError
        Syntax errors, anything but numbers and the operators above
        (names, calls, ...), division by zero, a non-finite result.

    Examples
    --------
    >>> evaluate("2 ** 3 / 4")
    2.0
    >>> evaluate("os.system", "stationary_ratio")
    Traceback (most recent call last):
    ...
    epicyclic.io.expressions.ExpressionError: stationary_ratio: 'os.system' may only contain numbers, + - * / ** and parentheses; found an attribute.
    """
    if not isinstance(text, str):
        raise ExpressionError(f"{field}: expected an expression string, got {text!r}.", str(text), field)
    if len(text) > MAX_LENGTH:
        raise ExpressionError(
            f"{field}: the expression is {len(text)} characters long; at most {MAX_LENGTH} are accepted.",
            text, field,
        )
    if not text.strip():
        raise ExpressionError(f"{field}: expected a number or an expression such as '(24/50)*(42/30)', "
                              "got an empty string.", text, field)
    try:
        with warnings.catch_warnings():  # "1if 2" warns about the literal: the error below says enough
            warnings.simplefilter("ignore")
            tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError:
        raise ExpressionError(
            f"{field}: {text!r} is not a valid arithmetic expression; write numbers with "
            "+ - * / ** and parentheses, e.g. '(24/50)*(42/30)'.", text, field,
        ) from None
    try:
        value = _eval(tree.body, text, field)
    except ZeroDivisionError:
        raise ExpressionError(f"{field}: {text!r} divides by zero.", text, field) from None
    except OverflowError:
        raise ExpressionError(f"{field}: {text!r} is too large.", text, field) from None
    if isinstance(value, complex) or not math.isfinite(value):
        raise ExpressionError(f"{field}: {text!r} does not give a finite real number.", text, field)
    return float(value)


_NAMES = {
    ast.Call: "a function call",
    ast.Name: "a name",
    ast.Attribute: "an attribute",
    ast.Subscript: "a subscript",
    ast.Compare: "a comparison",
    ast.BoolOp: "a boolean operator",
    ast.Lambda: "a lambda",
}


def _eval(node: ast.AST, text: str, field: str) -> float:
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            raise ExpressionError(
                f"{field}: {text!r} may only contain numbers, + - * / ** and parentheses; "
                f"found the constant {node.value!r}.", text, field,
            )
        return float(node.value)
    if isinstance(node, ast.UnaryOp) and type(node.op) in _UNARY:
        return _UNARY[type(node.op)](_eval(node.operand, text, field))
    if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
        left = _eval(node.left, text, field)
        right = _eval(node.right, text, field)
        if isinstance(node.op, ast.Pow) and abs(right) > MAX_EXPONENT:
            raise ExpressionError(
                f"{field}: {text!r} has the exponent {right:g}; at most ±{MAX_EXPONENT} is accepted.",
                text, field,
            )
        return _BINARY[type(node.op)](left, right)
    what = _NAMES.get(type(node))
    if what is None:
        op = getattr(node, "op", None)
        what = f"the operator {type(op).__name__}" if op is not None else f"a {type(node).__name__}"
    raise ExpressionError(
        f"{field}: {text!r} may only contain numbers, + - * / ** and parentheses; found {what}.",
        text, field,
    )
