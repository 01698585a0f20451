"""Trigger analysis of campaign results: behaviour table, derivation triggers, lift ranking, reports."""
