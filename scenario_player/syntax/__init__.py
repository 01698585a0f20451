"""OpenSCENARIO syntax: XML loading, parameters, catalogs, and typed records parsed from the resolved tree."""
