"""Studies built from the models: design tables, a bearing under load, the power-law fit,
reproductions of the papers."""
