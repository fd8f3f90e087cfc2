#!/usr/bin/env python3
"""Quarter annulus a <= r <= b, 0 <= theta <= 90 deg, of QUAD4 cells, as an Exodus II mesh.

usage: make_mesh.py OUT.e --inner a --outer b --radial NR --hoop NT

NR cells in r (uniform spacing (b - a) / NR), NT cells in theta (uniform, 90 / NT degrees).
Nodes lie on the circles; cell sides are straight chords. Sets:
  node sets  xaxis (theta = 0, the y = 0 edge), yaxis (theta = 90 deg, the x = 0 edge; x is
             written as exactly 0 there)
  side sets  inner (r = a), outer (r = b)

The file is written with netCDF4 (classic 64-bit-offset format) in the layout that libexodus
(and efg's `efg mesh`) writes: the variables src/io/ExodusReader.cpp reads through
ex_get_init / ex_get_coord / ex_get_block / ex_get_conn / ex_get_set / ex_get_names.
Node numbering: node (i, j) (i radial 0..NR, j hoop 0..NT) is j (NR + 1) + i + 1. Cell (i, j)
has nodes (i, j), (i+1, j), (i+1, j+1), (i, j+1): counter-clockwise, so Exodus QUAD4 side 2 is
r = r_(i+1) and side 4 is r = r_i.
"""
import argparse

import netCDF4
import numpy as np

LEN_NAME = 33  # maximum_name_length 32 + terminator, as libexodus writes it


def annulus(a, b, nr, nt):
    r = np.linspace(a, b, nr + 1)
    theta = np.linspace(0.0, 0.5 * np.pi, nt + 1)
    rr, tt = np.meshgrid(r, theta)  # [j, i]
    x = (rr * np.cos(tt)).ravel()
    y = (rr * np.sin(tt)).ravel()
    x[nt * (nr + 1):] = 0.0  # theta = 90 deg exactly on the axis
    y[: nr + 1] = 0.0

    def node(i, j):
        return j * (nr + 1) + i + 1

    conn = np.array([[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
                     for j in range(nt) for i in range(nr)], dtype=np.int32)

    def cell(i, j):
        return j * nr + i + 1

    node_sets = {
        "xaxis": np.array([node(i, 0) for i in range(nr + 1)], dtype=np.int32),
        "yaxis": np.array([node(i, nt) for i in range(nr + 1)], dtype=np.int32),
    }
    side_sets = {
        "inner": (np.array([cell(0, j) for j in range(nt)], dtype=np.int32),
                  np.full(nt, 4, dtype=np.int32)),
        "outer": (np.array([cell(nr - 1, j) for j in range(nt)], dtype=np.int32),
                  np.full(nt, 2, dtype=np.int32)),
    }
    return x, y, conn, node_sets, side_sets


def put_names(d, var, dim, names):
    v = d.createVariable(var, "S1", (dim, "len_name"))
    v[:] = netCDF4.stringtochar(np.array(names, dtype="S%d" % LEN_NAME))


def write_exodus(path, title, x, y, conn, node_sets, side_sets, block_name="annulus"):
    with netCDF4.Dataset(path, "w", format="NETCDF3_64BIT_OFFSET") as d:
        d.setncattr("api_version", np.float32(6.02))
        d.setncattr("version", np.float32(6.02))
        d.setncattr("floating_point_word_size", np.int32(8))
        d.setncattr("file_size", np.int32(1))
        d.setncattr("maximum_name_length", np.int32(32))
        d.setncattr("int64_status", np.int32(0))
        d.setncattr("title", title)
        d.createDimension("len_string", 33)
        d.createDimension("len_line", 81)
        d.createDimension("four", 4)
        d.createDimension("len_name", LEN_NAME)
        d.createDimension("time_step", None)
        d.createDimension("num_dim", 2)
        d.createDimension("num_nodes", len(x))
        d.createDimension("num_elem", len(conn))
        d.createDimension("num_el_blk", 1)
        d.createDimension("num_node_sets", len(node_sets))
        d.createDimension("num_side_sets", len(side_sets))
        d.createDimension("num_el_in_blk1", len(conn))
        d.createDimension("num_nod_per_el1", 4)
        for k, nodes in enumerate(node_sets.values(), 1):
            d.createDimension("num_nod_ns%d" % k, len(nodes))
        for k, (cells, _) in enumerate(side_sets.values(), 1):
            d.createDimension("num_side_ss%d" % k, len(cells))

        d.createVariable("time_whole", "f8", ("time_step",))
        for prefix, count_dim, count in (("eb", "num_el_blk", 1),
                                         ("ns", "num_node_sets", len(node_sets)),
                                         ("ss", "num_side_sets", len(side_sets))):
            d.createVariable(prefix + "_status", "i4", (count_dim,))[:] = np.ones(count, np.int32)
            prop = d.createVariable(prefix + "_prop1", "i4", (count_dim,))
            prop.setncattr("name", "ID")
            prop[:] = np.arange(1, count + 1, dtype=np.int32)
        d.createVariable("coordx", "f8", ("num_nodes",))[:] = x
        d.createVariable("coordy", "f8", ("num_nodes",))[:] = y
        put_names(d, "eb_names", "num_el_blk", [block_name])
        put_names(d, "ns_names", "num_node_sets", list(node_sets))
        put_names(d, "ss_names", "num_side_sets", list(side_sets))
        put_names(d, "coor_names", "num_dim", ["x", "y"])
        c = d.createVariable("connect1", "i4", ("num_el_in_blk1", "num_nod_per_el1"))
        c.setncattr("elem_type", "QUAD4")
        c[:] = conn
        for k, nodes in enumerate(node_sets.values(), 1):
            d.createVariable("node_ns%d" % k, "i4", ("num_nod_ns%d" % k,))[:] = nodes
        for k, (cells, sides) in enumerate(side_sets.values(), 1):
            d.createVariable("elem_ss%d" % k, "i4", ("num_side_ss%d" % k,))[:] = cells
            d.createVariable("side_ss%d" % k, "i4", ("num_side_ss%d" % k,))[:] = sides


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--inner", type=float, required=True)
    p.add_argument("--outer", type=float, required=True)
    p.add_argument("--radial", type=int, required=True)
    p.add_argument("--hoop", type=int, required=True)
    args = p.parse_args()
    if not (0 < args.inner < args.outer) or args.radial < 1 or args.hoop < 1:
        p.error("need 0 < inner < outer, radial >= 1, hoop >= 1")
    x, y, conn, ns, ss = annulus(args.inner, args.outer, args.radial, args.hoop)
    write_exodus(args.out, "thick cylinder quarter annulus a=%g b=%g %dx%d"
                 % (args.inner, args.outer, args.radial, args.hoop), x, y, conn, ns, ss)
    print("%s: %d nodes, %d QUAD4 cells" % (args.out, len(x), len(conn)))


if __name__ == "__main__":
    main()
