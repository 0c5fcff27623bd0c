#!/usr/bin/env python3
"""Lists the tests a ctest run skipped, and why; fails in CI on a skip not allowed.

    scripts/skipped-tests.py ALLOWED SUITE=JUNIT.xml [SUITE=JUNIT.xml ...]

JUNIT.xml: what `ctest --output-junit` wrote for one suite (scripts/test.sh's
release, asan, tsan). A test skips through its SKIP_RETURN_CODE (77: the Slurm
test) or GTEST_SKIP() (gtest_discover_tests' SKIP_REGULAR_EXPRESSION); the
reason is the test's own message: the text GTEST_SKIP() streamed, or the
line a script printed with "SKIPPED:". A test ctest did not run for another
reason (disabled, or never started) is listed too.

ALLOWED: the skips CI accepts, one a line, "SUITE TEST REASON" (TEST exact);
lines starting with '#' are comments. With SIMSWIFT_CI=1 (set by .ci/run: CI's machine is root
and has namespaces, so it can run everything) any other skip fails (exit 1).
"""
import os
import sys
import xml.etree.ElementTree as ET


def reason(output: str, message: str) -> str:
    lines = output.splitlines()
    # GTEST_SKIP() << why: "file:line: Skipped", then why, up to "[  SKIPPED ]".
    for i, line in enumerate(lines):
        if line.endswith(": Skipped"):
            why = []
            for rest in lines[i + 1:]:
                if rest.startswith("[  SKIPPED ]"):
                    break
                if rest.strip():
                    why.append(rest.strip())
            if why:
                return " ".join(why)
    for line in reversed(lines):
        if "SKIPPED:" in line:
            return line.split("SKIPPED:", 1)[1].strip()
    tail = [line.strip() for line in lines if line.strip()]
    return (tail[-1] if tail else "no output") + f" ({message})"


def main() -> int:
    allowed_file, suites = sys.argv[1], sys.argv[2:]
    allowed = {}
    with open(allowed_file, encoding="utf-8") as f:
        for number, raw in enumerate(f, 1):
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            parts = line.split(None, 2)
            if len(parts) < 3:
                print(f"{allowed_file}:{number}: expected SUITE TEST REASON", file=sys.stderr)
                return 2
            allowed[(parts[0], parts[1])] = parts[2]
    skipped = []
    for arg in suites:
        suite, path = arg.split("=", 1)
        if not os.path.exists(path):
            continue  # the suite did not run (an earlier stage failed, or it was left out)
        for case in ET.parse(path).getroot().iter("testcase"):
            if case.get("status") in ("run", "fail"):
                continue  # ran (a failure is ctest's to report, above these lines)
            mark = case.find("skipped")
            message = mark.get("message", "") if mark is not None else case.get("status", "")
            out = case.findtext("system-out") or ""
            skipped.append((suite, case.get("name"), reason(out, message)))
    ci = os.environ.get("SIMSWIFT_CI") == "1"
    refused = [s for s in skipped if (s[0], s[1]) not in allowed]
    print(f"simswift test.sh: {len(skipped)} test(s) skipped", file=sys.stderr)
    for suite, name, why in skipped:
        note = f" [allowed in CI: {allowed[(suite, name)]}]" if (suite, name) in allowed else ""
        print(f"  {suite}: {name}: {why}{note}", file=sys.stderr)
    if ci and refused:
        print(f"simswift test.sh: FAILED: {len(refused)} test(s) skipped that CI's machine runs "
              f"(SIMSWIFT_CI=1; a skip CI must accept goes in {allowed_file}, with its reason)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
