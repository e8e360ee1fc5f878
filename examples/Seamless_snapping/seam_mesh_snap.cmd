${SS_EXAMPLE_DATA}/data/meshes/bear.off ${SS_EXAMPLE_DATA}/examples/Surface_mesh_parameterization/data/bear.selection.txt ${SS_EXAMPLE_DATA}/bear_exact_uv.off
