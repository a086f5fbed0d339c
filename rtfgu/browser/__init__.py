"""The WGSL path in a web browser: a scene as a self-contained WebGPU page (export.py), and
the headless Chromium harness that renders such pages and reads their images back
(headless.py)."""
from .export import index_html, menu_page, page_html, scene_data, scene_page

__all__ = ["index_html", "menu_page", "page_html", "scene_data", "scene_page"]
