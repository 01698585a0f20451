"""Errors grouped by who is at fault, so a campaign never confuses a tool fault with an ADS failure.

- `InputError`: the user's input is wrong (malformed XML, a report with no text, an unknown entity reference).
- `UnsupportedFeature`: the input is valid but uses something this tool does not implement.
- `SimulationFault`: the harness itself broke while running (planner not responding, numerical blow-up).
- `SutFailure`: the system under test misbehaved; carried as a verdict, raised only where a run must stop.

Every error names where it happened (`source`: a file, a report id; `element`: an XML element, a field) so the CLI
prints one clear line instead of a traceback.
"""

from __future__ import annotations


class Txt2SceError(Exception):
    """Base of all errors raised on purpose by txt2sce."""

    def __init__(self, message: str, *, source: str | None = None, element: str | None = None,
                 line: int | None = None) -> None:
        self.message = message
        self.source = source
        self.element = element
        self.line = line
        super().__init__(self.__str__())

    def __str__(self) -> str:
        where = []
        if self.source:
            where.append(str(self.source))
        if self.line is not None:
            where.append(f"line {self.line}")
        if self.element:
            where.append(f"<{self.element}>" if not self.element.startswith(("<", "$", "/")) else self.element)
        prefix = ": ".join([", ".join(where)]) + ": " if where else ""
        return f"{prefix}{self.message}"


class InputError(Txt2SceError):
    """Bad input: the file, report or message itself is wrong."""


class UnsupportedFeature(Txt2SceError):
    """Valid input that uses a feature txt2sce does not implement."""


class SimulationFault(Txt2SceError):
    """The harness broke during a run (not the system under test's fault)."""


class SutFailure(Txt2SceError):
    """The system under test misbehaved."""
