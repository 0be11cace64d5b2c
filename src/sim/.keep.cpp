// Keeps the zcube_sim library non-empty while its folders fill up.
