#!/usr/bin/env python3
"""Runs a command with a pseudo-terminal for its stdin, stdout and stderr, as a person at a
terminal would, and writes everything it printed (bytes as they came, \\r and escapes
included) to OUTFILE. Exit status: the command's.

usage: pty_run.py OUTFILE COMMAND [ARGS...]"""
import os
import pty
import sys

out_path, argv = sys.argv[1], sys.argv[2:]
chunks = []


def read(fd):
    data = os.read(fd, 65536)
    chunks.append(data)
    return data


status = pty.spawn(argv, read)
with open(out_path, "wb") as f:
    f.write(b"".join(chunks))
sys.exit(os.waitstatus_to_exitcode(status) if hasattr(os, "waitstatus_to_exitcode")
         else (status >> 8))
