// A .geo with a syntax error on line 3 (missing closing brace).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0;
