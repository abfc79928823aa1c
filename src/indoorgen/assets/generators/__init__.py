"""Every generator module; importing this package registers them all."""
