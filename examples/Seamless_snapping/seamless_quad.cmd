${SS_EXAMPLE_DATA}/bear_parallelogram.obj ${SS_EXAMPLE_DATA}/bear_quads.ply --grid-scale 4 --report ${SS_EXAMPLE_DATA}/bear_quads.json
