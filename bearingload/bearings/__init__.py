"""Real bearings: designations, the catalogue and its data, clearance classes, life, resolving
a bearing to the inputs of a model."""
