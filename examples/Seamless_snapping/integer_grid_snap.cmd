${SS_EXAMPLE_DATA}/bear_parallelogram.obj 4 ${SS_EXAMPLE_DATA}/bear_igm.obj ${SS_EXAMPLE_DATA}/bear_igm.vval
