#!/usr/bin/env python3
"""on_terminal.py ERRFILE COMMAND...: runs COMMAND with its stderr on a pseudo-terminal (raw:
no newline translation) and its stdin and stdout as given; writes what it printed on stderr,
byte for byte, to ERRFILE and exits with its exit code."""
import os
import pty
import subprocess
import sys
import tty

err_file, command = sys.argv[1], sys.argv[2:]
master, slave = pty.openpty()
tty.setraw(slave)
process = subprocess.Popen(command, stderr=slave)
os.close(slave)
data = b""
while True:
    try:
        chunk = os.read(master, 65536)
    except OSError:  # EIO once the command has exited and closed the terminal
        break
    if not chunk:
        break
    data += chunk
os.close(master)
with open(err_file, "wb") as out:
    out.write(data)
sys.exit(process.wait())
