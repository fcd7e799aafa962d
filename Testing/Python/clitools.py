"""What the vtkshadows command-line tests share: running the program, failing
with a message, and the usage-error contract (exit status 2, a message on
stderr that starts with "vtkshadows: error:")."""
import subprocess
import sys


def run(program, *arguments):
    return subprocess.run([program, *arguments], capture_output=True, text=True, timeout=600)


def check(condition, message):
    if not condition:
        print("FAIL:", message)
        sys.exit(1)


def check_usage_error(program, arguments, expected):
    """Runs with bad arguments; returns the non-empty lines of stderr."""
    result = run(program, *arguments)
    check(result.returncode == 2, "%s: exit 2, got %d" % (arguments, result.returncode))
    check(expected in result.stderr and result.stderr.startswith("vtkshadows: error:"),
          "%s: message %r" % (arguments, result.stderr))
    return [line for line in result.stderr.splitlines() if line.strip()]
