"""Parameters: `$name` references and `${expr}` expressions (OpenSCENARIO 1.1 §9.1), resolved once at load.

Expressions allow + - * / % **, unary minus, parentheses, `not`/`and`/`or` and the functions round, floor, ceil,
sqrt, pow. esmini also accepts a string concatenation of bare words (`${Brake_ + $x}`); we do the same when the
arithmetic fails, because such names occur in real files (cut-in.xosc), and they are names, never numbers.
"""

from __future__ import annotations

import ast
import math
import operator
import re
from collections.abc import Mapping

from txt2sce_ros.errors import InputError

_REF = re.compile(r"\$([A-Za-z_][A-Za-z0-9_]*)")
_BINOPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
           ast.Mod: math.fmod, ast.Pow: operator.pow}
_FUNCS = {"round": lambda x: float(math.floor(x + 0.5)), "floor": math.floor, "ceil": math.ceil,
          "sqrt": math.sqrt, "pow": math.pow}


def _num(text: str) -> float | str:
    low = text.strip().lower()
    if low in ("true", "false"):
        return 1.0 if low == "true" else 0.0
    try:
        return float(text)
    except ValueError:
        return text


def _eval_node(node: ast.AST) -> float:
    if isinstance(node, ast.Expression):
        return _eval_node(node.body)
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
        return float(node.value)
    if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
        return float(_BINOPS[type(node.op)](_eval_node(node.left), _eval_node(node.right)))
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd, ast.Not)):
        val = _eval_node(node.operand)
        return -val if isinstance(node.op, ast.USub) else (val if isinstance(node.op, ast.UAdd) else float(not val))
    if isinstance(node, ast.BoolOp):
        vals = [_eval_node(v) for v in node.values]
        return float(all(vals)) if isinstance(node.op, ast.And) else float(any(vals))
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in _FUNCS:
        return float(_FUNCS[node.func.id](*[_eval_node(a) for a in node.args]))
    raise ValueError(f"unsupported expression element {type(node).__name__}")


def _fmt(value: float) -> str:
    """Format like esmini: integers without a decimal point, otherwise repr (round-trips exactly)."""
    return str(int(value)) if float(value).is_integer() and abs(value) < 1e15 else repr(float(value))


class ParameterScope:
    """A chain of name -> value (text) maps; inner declarations shadow outer ones."""

    def __init__(self, values: Mapping[str, str] | None = None, parent: "ParameterScope | None" = None) -> None:
        self.values: dict[str, str] = dict(values or {})
        self.parent = parent

    def child(self) -> "ParameterScope":
        return ParameterScope(parent=self)

    def lookup(self, name: str) -> str | None:
        scope: ParameterScope | None = self
        while scope is not None:
            if name in scope.values:
                return scope.values[name]
            scope = scope.parent
        return None

    def _get(self, name: str, source: str | None, element: str | None, line: int | None) -> str:
        val = self.lookup(name)
        if val is None:
            raise InputError(f"undeclared parameter ${name}", source=source, element=element, line=line)
        return val

    def resolve(self, text: str, *, source: str | None = None, element: str | None = None,
                line: int | None = None) -> str:
        """Resolve one attribute value: `$name`, `${expr}`, or a literal returned unchanged."""
        if not text or "$" not in text:
            return text
        stripped = text.strip()
        if stripped.startswith("${") and stripped.endswith("}"):
            return self._expression(stripped[2:-1], source, element, line)
        if _REF.fullmatch(stripped):
            return self._get(stripped[1:], source, element, line)
        # A reference embedded in a longer literal is not OpenSCENARIO; substitute anyway (esmini does).
        return _REF.sub(lambda m: self._get(m.group(1), source, element, line), text)

    def _expression(self, expr: str, source: str | None, element: str | None, line: int | None) -> str:
        values: dict[str, float | str] = {}

        def sub(match: re.Match[str]) -> str:
            key = f"_p{len(values)}"
            values[key] = _num(self._get(match.group(1), source, element, line))
            return key

        py = _REF.sub(sub, expr).replace("&&", " and ").replace("||", " or ").replace("!", " not ")
        try:
            tree = ast.parse(py.strip(), mode="eval")
            for node in ast.walk(tree):
                if isinstance(node, ast.Name) and node.id in values:
                    if isinstance(values[node.id], str):
                        raise ValueError("string operand")
            tree = _Substitute(values).visit(tree)
            return _fmt(_eval_node(tree))
        except (ValueError, SyntaxError, ZeroDivisionError, TypeError, OverflowError) as exc:
            # esmini's string concatenation: words and parameters joined by '+'.
            parts = [p.strip() for p in expr.split("+")]
            if parts and all(re.fullmatch(r"\$?[A-Za-z_0-9.]+", p) for p in parts):
                out = []
                for p in parts:
                    out.append(self._get(p[1:], source, element, line) if p.startswith("$") else p)
                return "".join(out)
            raise InputError(f"cannot evaluate expression ${{{expr}}}: {exc}", source=source, element=element,
                             line=line) from exc


class _Substitute(ast.NodeTransformer):
    def __init__(self, values: dict[str, float | str]) -> None:
        self.values = values

    def visit_Name(self, node: ast.Name) -> ast.AST:
        if node.id in self.values:
            return ast.copy_location(ast.Constant(value=self.values[node.id]), node)
        if node.id in _FUNCS:
            return node
        raise ValueError(f"unknown name {node.id}")
