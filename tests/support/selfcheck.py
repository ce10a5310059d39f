"""The bookkeeping the Python selftests share (tests/*/…_selftest.py): each check prints FAIL and
what failed (with `verbose`, "ok" and what held too), and finish() prints the tally and exits 1
when any check failed, 0 otherwise."""
import sys


class SelfCheck:
    def __init__(self, name, verbose=False):
        self.name, self.verbose, self.failures = name, verbose, []

    def __call__(self, ok, what, detail=""):
        if not ok:
            self.failures.append(what)
            print("FAIL: " + what + (": " + detail if detail else ""))
        elif self.verbose:
            print("ok:   " + what)
        return ok

    def finish(self):
        print(f"{self.name}:", "FAIL" if self.failures else "pass", f"({len(self.failures)} failure(s))")
        sys.exit(1 if self.failures else 0)
