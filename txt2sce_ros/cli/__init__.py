"""The `txt2sce` command-line tool. Each `cmd_*.py` module here adds one subcommand (see `main.py`)."""
