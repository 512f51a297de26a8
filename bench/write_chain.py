#!/usr/bin/python3
"""Writes the n-link 3D pendulum chain of tests/reference/chain.py as a .mbd model.

    write_chain.py N OUTPUT.mbd [--seed 1]

The model is named chain<N> (its C++ namespace in generated code).
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "tests", "reference"))
import chain  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("n", type=int)
    parser.add_argument("output")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    text = chain.to_mbd(chain.make_chain(args.n, args.seed))
    # Only rewrite when the text changes, so build systems see no new input.
    if os.path.exists(args.output):
        with open(args.output) as f:
            if f.read() == text:
                return 0
    with open(args.output, "w") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
