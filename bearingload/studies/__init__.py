"""The services behind the commands: a bearing under load (``solve``), the turning cage
(``sweep``) and the clearance that compensates it, the design tables and the life against
clearance (``table``), the power-law fit (``fit``), many cases at once (``batch``). Each returns
data; ``bearingload.reports`` renders it."""
