"""OpenSCENARIO helpers shared by the seed writer and the mutators: XSD validation, the ASAM quality checker and
the entity database (the XSD as a networkx graph) that supplies value domains and checks every written value."""

from .validate import QcIssue, is_valid, qc_check, qc_errors, validate_xosc

__all__ = ["QcIssue", "is_valid", "qc_check", "qc_errors", "validate_xosc"]
