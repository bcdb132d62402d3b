"""The pass/fail bookkeeping of the Python regression tests: one printed line per named check, and an exit
status that lists the checks that failed."""


class Checklist:
    def __init__(self):
        self.failures = []

    def expect(self, what, ok, detail=""):
        """Records check `what`: prints 'ok  ' or 'FAIL', the name and the detail."""
        print("%s %s %s" % ("ok  " if ok else "FAIL", what, detail))
        if not ok:
            self.failures.append(what)
        return ok

    def within(self, what, value, lo, hi):
        """Checks lo <= value <= hi."""
        return self.expect(what, lo <= value <= hi, "= %.6g (band [%g, %g])" % (value, lo, hi))

    def exit_status(self):
        """Prints the summary line; 0 when every check passed, 1 otherwise."""
        if self.failures:
            print("FAILED: " + ", ".join(self.failures))
            return 1
        print("all checks passed")
        return 0
