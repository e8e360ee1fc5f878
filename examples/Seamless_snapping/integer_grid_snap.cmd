${SS_EXAMPLE_DATA}/bear_orbifold.obj 1 ${SS_EXAMPLE_DATA}/bear_igm.obj ${SS_EXAMPLE_DATA}/bear_igm.vval
