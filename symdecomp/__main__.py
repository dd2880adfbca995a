from symdecomp.cli import entry

entry()
