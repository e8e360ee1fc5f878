${SS_EXAMPLE_DATA}/bear_orbifold.obj ${SS_EXAMPLE_DATA}/bear_constrained.obj
