"""`python -m indoorgen`: the same as the `indoorgen` command."""
import sys

from indoorgen.cli import main

sys.exit(main())
