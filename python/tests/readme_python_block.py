"""Runs the first ```python block of README.md as written (CTest test readme_python): in the current directory (CTest
runs it from the repository root, after execution___of__orbifold_to_exact wrote the bear map the block reads), with
the interpreter and PYTHONPATH it is given. Tracebacks name README.md and its line numbers.
usage: python3 readme_python_block.py README.md"""
import sys

path = sys.argv[1]
with open(path, encoding="utf-8") as f:
    lines = f.read().split("\n")
start = next(i for i, line in enumerate(lines) if line.strip() == "```python") + 1
end = next(i for i in range(start, len(lines)) if lines[i].strip() == "```")
code = "\n" * start + "\n".join(lines[start:end]) + "\n"      # the block at its own line numbers
exec(compile(code, path, "exec"), {"__name__": "__main__"})
print("readme_python: the first python block of %s (lines %d-%d) ran as written" % (path, start + 1, end))
