${SS_EXAMPLE_DATA}/bear_orbifold.obj ${SS_EXAMPLE_DATA}/bear_snapped.obj --report ${SS_EXAMPLE_DATA}/bear_report.json
