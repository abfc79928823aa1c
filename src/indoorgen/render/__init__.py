"""Pictures of scenes and assets: the top-down plan and shaded asset previews."""
