#version 3.7;
#declare A = array[10000][9000];
