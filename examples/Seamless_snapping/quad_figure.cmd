${SS_EXAMPLE_DATA}/data/meshes/bear.off ${SS_EXAMPLE_DATA}/quad_mesh.svg 16 ${SS_EXAMPLE_DATA}/bear_parallelogram.obj
