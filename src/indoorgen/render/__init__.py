"""Pictures: plan drawings of scenes (`plan`) and floorplans (`floorplan`), sharing `drawing`,
and shaded asset previews (`preview`)."""
