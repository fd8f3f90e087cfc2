"""Write a one-block Exodus II mesh with netCDF4 (classic 64-bit-offset format) in the layout
libexodus writes and efg reads (src/io/ExodusReader.cpp): the meshes of the verification
benchmarks (thick_cylinder/make_mesh.py: QUAD4 annulus; taylor_bar/make_mesh.py: HEX8 rod).
"""
import netCDF4
import numpy as np

LEN_NAME = 33  # maximum_name_length 32 + terminator, as libexodus writes it


def put_names(d, var, dim, names):
    v = d.createVariable(var, "S1", (dim, "len_name"))
    v[:] = netCDF4.stringtochar(np.array(names, dtype="S%d" % LEN_NAME))


def write_exodus(path, title, coords, conn, elem_type, node_sets, side_sets=None,
                 block_name="block_1", attributes=None, more_blocks=None):
    """coords: one array per dimension (x, y[, z]); conn: cells x nodes per cell (1-based);
    node_sets: name -> 1-based node ids; side_sets: name -> (1-based cells, 1-based sides);
    attributes: name -> one value per cell (the block's attributes, e.g. a shell thickness);
    more_blocks: further blocks after the first, (name, conn, elem_type) each (their cells
    numbered after the first block's)."""
    attributes = attributes or {}
    side_sets = side_sets or {}
    more_blocks = more_blocks or []
    dim = len(coords)
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
        d.createDimension("num_dim", dim)
        d.createDimension("num_nodes", len(coords[0]))
        d.createDimension("num_elem", len(conn) + sum(len(b[1]) for b in more_blocks))
        d.createDimension("num_el_blk", 1 + len(more_blocks))
        d.createDimension("num_node_sets", len(node_sets))
        if side_sets:
            d.createDimension("num_side_sets", len(side_sets))
        d.createDimension("num_el_in_blk1", len(conn))
        d.createDimension("num_nod_per_el1", np.shape(conn)[1])
        for k, nodes in enumerate(node_sets.values(), 1):
            d.createDimension("num_nod_ns%d" % k, len(nodes))
        for k, (cells, _) in enumerate(side_sets.values(), 1):
            d.createDimension("num_side_ss%d" % k, len(cells))

        d.createVariable("time_whole", "f8", ("time_step",))
        counts = [("eb", "num_el_blk", 1 + len(more_blocks)),
                  ("ns", "num_node_sets", len(node_sets))]
        if side_sets:
            counts.append(("ss", "num_side_sets", len(side_sets)))
        for prefix, count_dim, count in counts:
            d.createVariable(prefix + "_status", "i4", (count_dim,))[:] = np.ones(count, np.int32)
            prop = d.createVariable(prefix + "_prop1", "i4", (count_dim,))
            prop.setncattr("name", "ID")
            prop[:] = np.arange(1, count + 1, dtype=np.int32)
        for axis, values in zip("xyz", coords):
            d.createVariable("coord" + axis, "f8", ("num_nodes",))[:] = values
        put_names(d, "eb_names", "num_el_blk", [block_name] + [b[0] for b in more_blocks])
        put_names(d, "ns_names", "num_node_sets", list(node_sets))
        if side_sets:
            put_names(d, "ss_names", "num_side_sets", list(side_sets))
        put_names(d, "coor_names", "num_dim", list("xyz"[:dim]))
        c = d.createVariable("connect1", "i4", ("num_el_in_blk1", "num_nod_per_el1"))
        c.setncattr("elem_type", elem_type)
        c[:] = conn
        for k, (_, cells, cell_type) in enumerate(more_blocks, 2):
            d.createDimension("num_el_in_blk%d" % k, len(cells))
            d.createDimension("num_nod_per_el%d" % k, np.shape(cells)[1])
            c = d.createVariable("connect%d" % k, "i4",
                                 ("num_el_in_blk%d" % k, "num_nod_per_el%d" % k))
            c.setncattr("elem_type", cell_type)
            c[:] = cells
        if attributes:
            d.createDimension("num_att_in_blk1", len(attributes))
            a = d.createVariable("attrib1", "f8", ("num_el_in_blk1", "num_att_in_blk1"))
            a[:] = np.array(list(attributes.values())).T
            put_names(d, "attrib_name1", "num_att_in_blk1", list(attributes))
        for k, nodes in enumerate(node_sets.values(), 1):
            d.createVariable("node_ns%d" % k, "i4", ("num_nod_ns%d" % k,))[:] = nodes
        for k, (cells, sides) in enumerate(side_sets.values(), 1):
            d.createVariable("elem_ss%d" % k, "i4", ("num_side_ss%d" % k,))[:] = cells
            d.createVariable("side_ss%d" % k, "i4", ("num_side_ss%d" % k,))[:] = sides
