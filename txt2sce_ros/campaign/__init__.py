"""Campaigns: reports -> seeds -> trees -> closed-loop runs -> verdicts -> analysis, resumable and parallel."""
