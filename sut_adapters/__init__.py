"""Adapters that put third-party planners under test on txt2sce's topic interface (docs/ads_interface.md).

Each adapter is a system under test, like `standin_planner`, and is kept apart from the harness: it runs in its own
environment (its planner's dependencies can clash with ours) and talks to the graph only over the documented topics.
"""
