// quadrature rules: filled in by the element work
