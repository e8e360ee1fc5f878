"""A cut mesh made from an OBJ map, for the command-line tests: one 'v' per 'vt' (the vertices duplicated along the
seams), as libigl and Directional write their parametrizations."""


def write_cut_mesh(src, path):
    def records(kind):
        with open(src) as f:
            return [l.split()[1:] for l in f if l.split() and l.split()[0] == kind]
    v, vt, faces = records("v"), records("vt"), records("f")
    pos = [None] * len(vt)
    for f in faces:
        for c in f:
            a, b = (int(x) for x in c.split("/")[:2])
            pos[b - 1] = v[a - 1]
    with open(path, "w") as o:
        for p in pos:
            o.write("v %s\n" % " ".join(p))
        for t in vt:
            o.write("vt %s\n" % " ".join(t))
        for f in faces:
            o.write("f %s\n" % " ".join("%s/%s" % (c.split("/")[1], c.split("/")[1]) for c in f))
