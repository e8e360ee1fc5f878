${SS_EXAMPLE_DATA}/bear_orbifold.obj ${SS_EXAMPLE_DATA}/bear_motorcycle_graph.svg
