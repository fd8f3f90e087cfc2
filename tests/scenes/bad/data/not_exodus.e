this is not an Exodus file
