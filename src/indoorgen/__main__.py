import sys

from indoorgen.cli import main

sys.exit(main())
