"""Runs the ```python blocks of README.md as written, in order and in one namespace (CTest test readme_python): in the
current directory (CTest runs it from the repository root, after execution___of__orbifold_to_exact and
execution___of__quad_figure wrote the bear maps the blocks read), with the interpreter and PYTHONPATH it is given.
Tracebacks name README.md and its line numbers.
usage: python3 readme_python_block.py README.md"""
import sys

path = sys.argv[1]
with open(path, encoding="utf-8") as f:
    lines = f.read().split("\n")
namespace = {"__name__": "__main__"}
ranges = []
for first in [i + 1 for i, line in enumerate(lines) if line.strip() == "```python"]:
    end = next(i for i in range(first, len(lines)) if lines[i].strip() == "```")
    code = "\n" * first + "\n".join(lines[first:end]) + "\n"      # the block at its own line numbers
    exec(compile(code, path, "exec"), namespace)
    ranges.append("%d-%d" % (first + 1, end))
print("readme_python: the %d python blocks of %s (lines %s) ran as written" % (len(ranges), path, ", ".join(ranges)))
