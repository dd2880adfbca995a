import sys

from symdecomp.cli import main

sys.exit(main())
