"""The test input with fold-overs of cli_test.py and quad_cli_test.py: a 3 x 3 grid of unit squares (two triangles
each) whose vertex (1, 1) has the UV (3, 1), so that two UV triangles flip and two have zero area. It has no seam, so
it is an exact integer-grid map as it is."""


def write_fold_over_grid(path):
    with open(path, "w") as o:
        for j in range(4):
            for i in range(4):
                o.write("v %d %d 0\n" % (i, j))
        for j in range(4):
            for i in range(4):
                o.write("vt %d %d\n" % ((3, 1) if (i, j) == (1, 1) else (i, j)))
        for j in range(3):
            for i in range(3):
                a, b, c, d = 4 * j + i + 1, 4 * j + i + 2, 4 * (j + 1) + i + 2, 4 * (j + 1) + i + 1
                o.write("f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n" % (a, a, b, b, c, c, a, a, c, c, d, d))
