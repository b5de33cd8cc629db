# Writes the real half of data/corpus/: point patterns of Debian's r-cran-spatstat.data
# (GPL-2 or later; the data sets' sources are in its documentation, ?longleaf and so on).
# Trees with diameters become discs of their size: a `radius` column in the window's units.
# Run from the repository root: Rscript data/tools/export_spatstat.R
library(spatstat.data)
out <- "data/corpus"
write_pattern <- function(name, category, radius = NULL) {
  d <- get(name)
  rows <- data.frame(x = round(d$x, 4), y = round(d$y, 4), category = category)
  if (!is.null(radius)) rows$radius <- signif(radius, 4)
  write.csv(rows, file.path(out, paste0(name, ".csv")), row.names = FALSE, quote = FALSE)
  cat(name, d$n, "window", d$window$xrange, d$window$yrange, "\n")
}
write_pattern("longleaf", "tree", longleaf$marks / 200)   # dbh in cm, window in metres
write_pattern("spruces", "tree", spruces$marks / 2)       # dbh in metres
# diameters in cm, window in metres; 0 (below 1 cm) is read as 0.5 cm
write_pattern("finpines", "tree", pmax(finpines$marks$diameter, 0.5) / 200)
write_pattern("amacrine", as.character(amacrine$marks))
write_pattern("lansing", as.character(lansing$marks))
write_pattern("betacells", as.character(betacells$marks$type), sqrt(betacells$marks$area / pi))
write_pattern("redwood", "tree")
write_pattern("cells", "cell")
