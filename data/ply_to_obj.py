#!/usr/bin/env python3
"""Convert an ASCII PLY triangle mesh (x y z vertices, vertex_indices faces) to OBJ."""
import sys


def main(src: str, dst: str) -> None:
    with open(src, "r", encoding="ascii") as f:
        if f.readline().strip() != "ply":
            sys.exit(f"{src}: not a PLY file")
        vertices = faces = None
        vertex_props = []
        element = None
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "format" and words[1] != "ascii":
                sys.exit(f"{src}: only ASCII PLY is supported here, got {words[1]}")
            if words[0] == "element":
                element = words[1]
                if element == "vertex":
                    vertices = int(words[2])
                elif element == "face":
                    faces = int(words[2])
            elif words[0] == "property" and element == "vertex":
                vertex_props.append(words[-1])
            elif words[0] == "end_header":
                break
        if vertices is None or faces is None:
            sys.exit(f"{src}: header lacks vertex or face elements")
        ix, iy, iz = (vertex_props.index(a) for a in "xyz")
        with open(dst, "w", encoding="ascii") as out:
            for _ in range(vertices):
                w = f.readline().split()
                out.write(f"v {w[ix]} {w[iy]} {w[iz]}\n")
            for _ in range(faces):
                w = f.readline().split()
                n = int(w[0])
                out.write("f " + " ".join(str(int(i) + 1) for i in w[1 : 1 + n]) + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
