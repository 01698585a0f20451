"""Benchmarks behind `txt2sce bench NAME`: one module per name, each with DESCRIPTION and run(args)."""
