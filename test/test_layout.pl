/*  Tests of the library's layout (STYLE.md rules 1 and 24): one library
    root, imports through library(oro/...), no import cycle, no module
    past the length guide.
*/

:- module(test_layout, []).
:- use_module(library(plunit)).
:- use_module(library(prolog_xref)).
:- use_module(library(ugraphs)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(readutil)).
:- use_module(library(filesex)).
:- use_module(oro_test_support).

%   library_file(-File): every Prolog file under prolog/, absolute.

library_file(File) :-
    test_checkout_path(prolog, Root),
    directory_member(Root, File,
                     [ recursive(true),
                       extensions([pl])
                     ]).

file_lines(File, Count) :-
    read_file_to_codes(File, Codes, []),
    aggregate_all(count, member(0'\n, Codes), Count).

%   The import graph of prolog/: an edge from each file to every file
%   of prolog/ it loads, as prolog_xref reads its directives.

import_edges(Files, File, Edges) :-
    xref_source(File, [silent(true)]),
    findall(File-Used,
            ( xref_uses_file(File, _Spec, Used),
              memberchk(Used, Files)
            ),
            Edges0),
    sort(Edges0, Edges).

%   cycle(+Graph, -Cycle): Cycle is the sorted set of files of a strongly
%   connected component of more than one file (or a file importing
%   itself).

cycle(Graph, Cycle) :-
    transitive_closure(Graph, Closure),
    member(File-Reached, Closure),
    memberchk(File, Reached),
    findall(Other,
            ( member(Other, Reached),
              memberchk(Other-Back, Closure),
              memberchk(File, Back)
            ),
            Cycle0),
    sort([File|Cycle0], Cycle).

:- begin_tests(layout).

test(no_relative_imports, Found == []) :-
    findall(File-Line,
            ( library_file(File),
              read_file_to_string(File, Text, []),
              split_string(Text, "\n", "", Lines),
              nth1(Line, Lines, L),
              sub_string(L, _, _, _, "'../")
            ),
            Found).

test(server_holds_only_the_script, Files == ['oro_server.pl']) :-
    test_checkout_path(server, Dir),
    directory_files(Dir, Entries),
    exclude([E]>>sub_atom(E, 0, _, _, '.'), Entries, Files0),
    msort(Files0, Files).

test(no_module_past_1500_lines, Long == []) :-
    findall(File-Count,
            ( library_file(File),
              file_lines(File, Count),
              Count > 1500
            ),
            Long).

test(no_import_cycle, Cycles == []) :-
    findall(File, library_file(File), Files),
    maplist(import_edges(Files), Files, Edgess),
    append(Edgess, Edges),
    vertices_edges_to_ugraph(Files, Edges, Graph),
    findall(Cycle, cycle(Graph, Cycle), Cycles0),
    sort(Cycles0, Cycles).

:- end_tests(layout).
