"""`python3 -m grainlab.report RUN_DIR [RUN_DIR ...] [--out DIR]` (cli.py)."""

import sys

from .cli import main

sys.exit(main())
