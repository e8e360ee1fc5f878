${SS_EXAMPLE_DATA}/bear_orbifold.obj --json ${SS_EXAMPLE_DATA}/bear_trace.json --svg ${SS_EXAMPLE_DATA}/bear_trace.svg
