"""How good a generated scene is, by measure: layout rules a designer would check, the community's
published scene measures, and navigation for a robot. Nothing here changes a scene; the pipeline
writes the results into report.json."""
