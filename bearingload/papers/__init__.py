"""The papers checked: every number they print that the package recomputes (errata, the
published values), Kurochkin's (1973) statics and tables, the varying-compliance abstract's fits
and the crane paper's (2009) stiffness procedure. Each module returns data; ``bearingload.reports``
renders it."""
