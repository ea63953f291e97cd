#!/usr/bin/env python3
"""mms scripted client for the tests: each argument is one command,
'COMMAND=ANSWER' (the answer must match) or 'COMMAND' (no answer expected).
Prints 'script: N checks ok' on stderr and exits 0, or names the first
failed check and exits 1."""
import sys

checks = 0
for arg in sys.argv[1:]:
    line, eq, want = arg.partition("=")
    sys.stdout.write(line + "\n")
    sys.stdout.flush()
    if not eq:
        continue
    got = sys.stdin.readline().rstrip("\n")
    if got != want:
        sys.stderr.write("script: FAILED %r -> %r (want %r)\n" % (line, got, want))
        sys.exit(1)
    checks += 1
sys.stderr.write("script: %d checks ok\n" % checks)
