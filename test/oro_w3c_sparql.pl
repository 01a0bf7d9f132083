:- module(oro_w3c_sparql,
          [ w3c_suite_dir/1,            % -Dir
            w3c_tests/2,                % +Dir, -Tests
            w3c_run/4,                  % +Port, +Test, -Outcome, -Detail
            w3c_category/2              % +Test, -Category
          ]).
:- use_module(library(semweb/turtle)).
:- use_module(library(semweb/rdf_db), [rdf_is_bnode/1]).
:- use_module(library(rdf), [load_rdf/3]).
:- use_module(library(sgml)).
:- use_module(library(http/http_open)).
:- use_module(library(http/json)).
:- use_module(library(uri)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(readutil)).
:- use_module(library(dcg/basics)).
:- use_module(library(pcre)).
:- use_module(library(oro/sparql/oro_sparql), [oro_sparql_graph/2]).
:- use_module(library(oro/oro_store), [oro_load_ontology/1]).
:- use_module(oro_test_support, [test_checkout_path/2]).

/** <module> The W3C SPARQL test suites, run through the endpoint

Reads the manifests of ../shared/w3c-sparql/ (SPARQL 1.0 data-r2 and
the SPARQL 1.1 query and result-format folders) and runs each
applicable test through /sparql of a running server, as a SPARQL client
would: query evaluation tests (and the CSV/TSV format tests) with
infer=false, the test's data files as default-graph-uri and its
qt:graphData as named-graph-uri, the expected results (.srx, .srj,
.tsv, .csv, result sets and graphs in Turtle or RDF/XML) compared with
the full table the endpoint returns (a bag of rows, in order under
ORDER BY, blank nodes up to renaming, datatypes and language tags
included); syntax tests by the status of the answer (400 or not).

Data files are loaded into the store with oro_load_ontology/1, so each
is the graph named by its file:// URL.  A query is sent with `BASE
<file URL of the query>` before its text, so that FROM <data.ttl> names
the graph of that file; the IRIs of the answers under the suite's
folder are then read back as the W3C IRIs the expected results use
(file:///…/sparql10/x ↔ http://www.w3.org/2001/sw/DataAccess/tests/data-r2/x).
*/

w3c_suite_dir(Dir) :-
    test_checkout_path('../shared/w3c-sparql', Dir),
    exists_directory(Dir).

mf(Local, IRI) :-
    atom_concat('http://www.w3.org/2001/sw/DataAccess/tests/test-manifest#', Local, IRI).
qt(Local, IRI) :-
    atom_concat('http://www.w3.org/2001/sw/DataAccess/tests/test-query#', Local, IRI).
rdf_type('http://www.w3.org/1999/02/22-rdf-syntax-ns#type').
rs(Local, IRI) :-
    atom_concat('http://www.w3.org/2001/sw/DataAccess/tests/result-set#', Local, IRI).

%   suite_base(?Suite, ?W3CBase)

suite_base(sparql10, 'http://www.w3.org/2001/sw/DataAccess/tests/data-r2/').
suite_base(sparql11, 'http://www.w3.org/2009/sparql/docs/tests/data-sparql11/').

top_manifest(sparql10, 'manifest.ttl').
top_manifest(sparql11, 'manifest-sparql11-query.ttl').
top_manifest(sparql11, 'manifest-sparql11-results.ttl').

%!  w3c_tests(+Dir, -Tests) is det.
%
%   Tests are the applicable tests of the suites under Dir, each
%   test(Suite, Folder, Name, Type, Query, Data, GraphData, Result):
%   Type `eval`, `positive` or `negative`; file names absolute.

w3c_tests(Dir, Tests) :-
    findall(Suite-File, ( top_manifest(Suite, Top),
                          atomic_list_concat([Dir, Suite, Top], '/', TopFile),
                          included(TopFile, File)
                        ), Pairs0),
    sort(Pairs0, Pairs),
    findall(T, ( member(Suite-File, Pairs),
                 manifest_test(Suite, File, T)
               ), Tests0),
    sort(Tests0, Tests).

included(Top, File) :-
    read_ttl(Top, Ts),
    mf(include, Include),
    (   member(rdf(_, Include, List), Ts)
    ->  collection(Ts, List, Items),
        member(URL, Items),
        uri_file_name(URL, File)
    ;   File = Top
    ).

read_ttl(File, Triples) :-
    uri_file_name(URL, File),
    rdf_read_turtle(File, Triples, [base_uri(URL)]).

collection(_, 'http://www.w3.org/1999/02/22-rdf-syntax-ns#nil', []) :- !.
collection(Ts, Node, [X|Xs]) :-
    memberchk(rdf(Node, 'http://www.w3.org/1999/02/22-rdf-syntax-ns#first', X), Ts),
    memberchk(rdf(Node, 'http://www.w3.org/1999/02/22-rdf-syntax-ns#rest', Next), Ts),
    collection(Ts, Next, Xs).

manifest_test(Suite, File, test(Suite, Folder, Name, Type, Query, Data, GraphData, Result)) :-
    file_directory_name(File, FolderPath),
    file_base_name(FolderPath, Folder),
    \+ excluded_folder(Folder),
    read_ttl(File, Ts),
    mf(entries, Entries),
    memberchk(rdf(_, Entries, List), Ts),
    collection(Ts, List, Items),
    member(Test, Items),
    rdf_type(RdfType),
    memberchk(rdf(Test, RdfType, TypeIRI), Ts),
    test_type(TypeIRI, Type),
    \+ member(rdf(Test, 'http://www.w3.org/2001/sw/DataAccess/tests/test-dawg#approval',
                  'http://www.w3.org/2001/sw/DataAccess/tests/test-dawg#Withdrawn'), Ts),
    mf(name, NameP),
    (   memberchk(rdf(Test, NameP, literal(Name0)), Ts)
    ->  literal_text(Name0, Name)
    ;   Name = Test
    ),
    mf(action, ActionP),
    memberchk(rdf(Test, ActionP, Action), Ts),
    (   Type == eval
    ->  qt(query, QueryP),
        memberchk(rdf(Action, QueryP, QueryURL), Ts),
        \+ ( qt(serviceData, SD), memberchk(rdf(Action, SD, _), Ts) ),
        qt(data, DataP),
        findall(F, ( member(rdf(Action, DataP, U), Ts), uri_file_name(U, F) ), Data),
        qt(graphData, GDP),
        findall(F, ( member(rdf(Action, GDP, U), Ts), uri_file_name(U, F) ), GraphData),
        mf(result, ResultP),
        memberchk(rdf(Test, ResultP, ResultURL), Ts),
        uri_file_name(ResultURL, Result)
    ;   QueryURL = Action,
        Data = [],
        GraphData = [],
        Result = none
    ),
    uri_file_name(QueryURL, Query).

literal_text(type(_, T), T) :- !.
literal_text(lang(_, T), T) :- !.
literal_text(T, T).

excluded_folder(entailment).
excluded_folder(service).
excluded_folder('syntax-fed').

test_type(IRI, Type) :-
    mf(Local, IRI),
    local_type(Local, Type).

local_type('QueryEvaluationTest', eval).
local_type('CSVResultFormatTest', eval).
local_type('PositiveSyntaxTest', positive).
local_type('PositiveSyntaxTest11', positive).
local_type('NegativeSyntaxTest', negative).
local_type('NegativeSyntaxTest11', negative).

%!  w3c_category(+Test, -Category) is det.

w3c_category(test(Suite, Folder, _, _, _, _, _, _), Category) :-
    atomic_list_concat([Suite, Folder], '/', Category).

		 /*******************************
		 *             RUN              *
		 *******************************/

%!  w3c_run(+Port, +Test, -Outcome, -Detail) is det.
%
%   Outcome is `pass` or `fail`; Detail says why it failed.

w3c_run(Port, Test, Outcome, Detail) :-
    catch(run(Port, Test, Outcome, Detail), E,
          ( Outcome = fail,
            message_to_detail(E, Detail)
          )),
    !.
w3c_run(_, _, fail, "harness failed").

message_to_detail(E, Detail) :-
    format(string(Detail), "exception ~q", [E]).

run(Port, test(Suite, _, _, Type, Query, Data, GraphData, Result), Outcome, Detail) :-
    read_file_to_string(Query, Text0, [encoding(utf8)]),
    uri_file_name(QueryURL, Query),
    format(string(Text), "BASE <~w>~n~s", [QueryURL, Text0]),
    (   Type == eval
    ->  from_files(Text0, Query, FromFiles),
        maplist(ensure_loaded_data, FromFiles),
        maplist(ensure_loaded_data, Data),
        maplist(ensure_loaded_data, GraphData),
        maplist(file_url, Data, DataURLs),
        maplist(file_url, GraphData, GraphURLs),
        dataset_params(Text0, DataURLs, GraphURLs, Params),
        expected(Result, Expected0),
        w3c_iris(Suite, Expected0, Expected),
        accept(Expected, Accept),
        request(Port, Text, Params, Accept, Status, Type1, Body),
        (   Status == 200
        ->  actual(Type1, Body, Suite, Actual),
            (   same_result(Expected, Actual, Text0)
            ->  Outcome = pass,
                Detail = ""
            ;   Outcome = fail,
                format(string(Detail), "different result: got ~q", [Actual])
            )
        ;   Outcome = fail,
            format(string(Detail), "status ~w: ~s", [Status, Body])
        )
    ;   request(Port, Text, ['default-graph-uri'='urn:oro:w3c:empty'],
                'application/sparql-results+json, text/turtle', Status, _, Body),
        (   Type == positive
        ->  (   Status \== 400
            ->  Outcome = pass, Detail = ""
            ;   Outcome = fail, format(string(Detail), "rejected: ~s", [Body])
            )
        ;   (   Status == 400
            ->  Outcome = pass, Detail = ""
            ;   Outcome = fail, format(string(Detail), "accepted (status ~w)", [Status])
            )
        )
    ).

%   from_files(+Query, +QueryFile, -Files): the existing files the
%   query's FROM and FROM NAMED name relative to the query file.

from_files(Text, QueryFile, Files) :-
    file_directory_name(QueryFile, Dir),
    re_foldl(add_from(Dir), "FROM\\s+(?:NAMED\\s+)?<([^>:]*)>"/i, Text, [], Files0, []),
    sort(Files0, Files).

add_from(Dir, Match, Files, [File|Files]) :-
    get_dict(1, Match, Rel),
    atomic_list_concat([Dir, Rel], '/', File),
    exists_file(File),
    !.
add_from(_, _, Files, Files).

file_url(File, URL) :-
    uri_file_name(URL, File).

ensure_loaded_data(File) :-
    file_url(File, URL),
    (   oro_sparql_graph(URL, _)
    ->  true
    ;   oro_load_ontology(File)
    ).

%   dataset_params(+Query, +Data, +GraphData, -Params): the test's data
%   as default-graph-uri and named-graph-uri, unless the query has FROM
%   (the protocol's parameters would override it); a query without data
%   and without FROM gets an empty default graph.

dataset_params(Query, _, _, Params) :-
    re_match("\\bFROM\\b"/i, Query),
    !,
    Params = [].                % the query names its dataset itself
dataset_params(_, [], [], Params) :-
    !,
    Params = ['default-graph-uri'='urn:oro:w3c:empty'].
dataset_params(_, Data, GraphData, Params) :-
    findall('default-graph-uri'=U, member(U, Data), P1),
    findall('named-graph-uri'=U, member(U, GraphData), P2),
    append(P1, P2, Params0),
    (   Data == []
    ->  Params = ['default-graph-uri'='urn:oro:w3c:empty'|Params0]
    ;   Params = Params0
    ).

request(Port, Text, Params, Accept, Status, Type, Body) :-
    format(atom(URL), 'http://127.0.0.1:~w/sparql', [Port]),
    append(Params, [infer=false], Params1),
    uri_query_components(Search, Params1),
    atomic_list_concat([URL, '?', Search], Full),
    string_codes(Text, Codes),
    setup_call_cleanup(
        http_open(Full, In, [ method(post),
                              post(codes('application/sparql-query; charset=UTF-8', Codes)),
                              request_header('Accept'=Accept),
                              status_code(Status),
                              header(content_type, Type),
                              timeout(60)
                            ]),
        ( set_stream(In, encoding(utf8)),
          read_string(In, _, Body)
        ),
        close(In)).

		 /*******************************
		 *        EXPECTED RESULTS      *
		 *******************************/

%   Results: table(Vars, Rows), boolean(B), graph(Triples),
%   csv(Rows) (rows of strings).  Rows are lists of Var-Term, sorted;
%   terms iri(I), bnode(L), lit(Lex, Tag) with Tag lang(L), type(T)
%   or plain.

expected(File, Result) :-
    file_name_extension(_, Ext, File),
    expected(Ext, File, Result).

expected(srx, File, Result) :-
    load_xml(File, DOM, [space(preserve), dialect(xmlns)]),   % literals keep newlines
    srx_result(DOM, Result).
expected(srj, File, Result) :-
    setup_call_cleanup(open(File, read, In, [encoding(utf8)]),
                       json_read_dict(In, Dict),
                       close(In)),
    json_result(Dict, Result).
expected(tsv, File, Result) :-
    read_file_to_string(File, Text, [encoding(utf8)]),
    tsv_result(Text, Result).
expected(csv, File, csv(Vars, Rows)) :-
    read_file_to_string(File, Text, [encoding(utf8)]),
    csv_rows(Text, [Vars|Rows]).
expected(ttl, File, Result) :-
    read_ttl(File, Ts),
    rdf_result(Ts, Result).
expected(rdf, File, Result) :-
    load_rdf(File, Ts, [blank_nodes(noshare)]),
    rdf_result(Ts, Result).

accept(table(_, _), 'application/sparql-results+json').
accept(boolean(_), 'application/sparql-results+json').
accept(graph(_), 'application/n-triples').
accept(csv(_, _), 'text/csv').
accept(tsv(_, _), 'text/tab-separated-values').

%   srx_result(+DOM, -Result)

srx_result(DOM, Result) :-
    member(element(_:sparql, _, Content), DOM),
    (   member(element(_:boolean, _, [B]), Content)
    ->  Result = boolean(B)
    ;   member(element(_:head, _, Head), Content),
        findall(V, member(element(_:variable, [name=V], _), Head), Vars),
        member(element(_:results, _, Results), Content),
        findall(Row, ( member(element(_:result, _, Bs), Results),
                       findall(N-T, ( member(element(_:binding, [name=N], Cs), Bs),
                                      member(E, Cs),
                                      E = element(_, _, _),
                                      srx_term(E, T)
                                    ), Row0),
                       sort(Row0, Row)
                     ), Rows),
        Result = table(Vars, Rows)
    ).

srx_term(element(_:uri, _, Text), iri(I)) :- !, content_atom(Text, I).
srx_term(element(_:bnode, _, Text), bnode(L)) :- !, content_atom(Text, L).
srx_term(element(_:literal, Attrs, Text), lit(Lex, Tag)) :-
    content_atom(Text, Lex),
    (   member(Lang=L, Attrs), lang_attr(Lang)
    ->  downcase_atom(L, LL), Tag = lang(LL)
    ;   memberchk(datatype=T, Attrs)
    ->  Tag = type(T)
    ;   Tag = plain
    ).

lang_attr(xml:lang).
lang_attr('xml:lang').
lang_attr(lang).
lang_attr(_:lang).

content_atom([], '') :- !.
content_atom([A], A) :- atom(A), !.
content_atom(L, A) :- atomic_list_concat(L, A).

json_result(Dict, boolean(B)) :-
    get_dict(boolean, Dict, B0),
    !,
    atom_string(B, B0).
json_result(Dict, table(Vars, Rows)) :-
    maplist(atom_string, Vars, Dict.head.vars),
    findall(Row, ( member(B, Dict.results.bindings),
                   dict_pairs(B, _, Pairs),
                   findall(N-T, ( member(N-V, Pairs), json_term(V, T) ), Row0),
                   sort(Row0, Row)
                 ), Rows).

json_term(V, T) :-
    atom_string(Type, V.type),
    atom_string(Value, V.value),
    (   Type == uri
    ->  T = iri(Value)
    ;   Type == bnode
    ->  T = bnode(Value)
    ;   get_dict('xml:lang', V, L)
    ->  atom_string(LA, L), downcase_atom(LA, LL), T = lit(Value, lang(LL))
    ;   get_dict(datatype, V, D)
    ->  atom_string(DA, D), T = lit(Value, type(DA))
    ;   T = lit(Value, plain)
    ).

tsv_result(Text, tsv(Vars, Rows)) :-
    split_string(Text, "\n", "\r", Lines0),
    exclude(==(""), Lines0, [Header|Lines]),
    split_string(Header, "\t", "", Hs),
    maplist(tsv_var, Hs, Vars),
    findall(Row, ( member(L, Lines),
                   split_string(L, "\t", "", Fields),
                   foldl(tsv_binding, Vars, Fields, Row0, []),
                   sort(Row0, Row)
                 ), Rows).

tsv_var(H, V) :-
    (   sub_string(H, 0, 1, _, "?")
    ->  sub_atom(H, 1, _, 0, V)
    ;   atom_string(V, H)
    ).

tsv_binding(_, "", Row, Row) :- !.
tsv_binding(V, Field, [V-T|Row], Row) :-
    turtle_term(Field, T).

turtle_term(Field, T) :-
    format(string(Doc), "<urn:s> <urn:p> ~s .", [Field]),
    setup_call_cleanup(open_string(Doc, In),
                       rdf_read_turtle(stream(In), [rdf(_, _, O)], []),
                       close(In)),
    rdf_term(O, T).

rdf_term(literal(L), lit(Lex, Tag)) :-
    !,
    (   L = lang(Lang, Lex0)
    ->  downcase_atom(Lang, LL), Tag = lang(LL)
    ;   L = type(Type, Lex0)
    ->  Tag = type(Type)
    ;   Lex0 = L, Tag = plain
    ),
    (   atom(Lex0) -> Lex = Lex0 ; format(atom(Lex), '~w', [Lex0]) ).
rdf_term(node(N), bnode(L)) :-
    !,
    format(atom(L), 'n~w', [N]).
rdf_term(X, bnode(X)) :-
    rdf_is_bnode(X),
    !.
rdf_term(X, bnode(X)) :-
    sub_atom(X, 0, _, _, '__'),
    !.
rdf_term(X, iri(X)).

csv_rows(Text, Rows) :-
    string_codes(Text, Codes),
    phrase(csv_lines(Rows), Codes).

csv_lines([]) --> eos, !.
csv_lines([R|Rs]) --> csv_fields(R), ( "\r\n" ; "\n" ; eos ), !, csv_lines(Rs).

csv_fields([F|Fs]) --> csv_field(F), ( "," -> csv_fields(Fs) ; { Fs = [] } ).

csv_field(F) --> "\"", !, quoted(Cs), { string_codes(F, Cs) }.
csv_field(F) --> plain_field(Cs), { string_codes(F, Cs) }.

quoted([0'"|Cs]) --> "\"\"", !, quoted(Cs).
quoted([]) --> "\"", !.
quoted([C|Cs]) --> [C], quoted(Cs).

plain_field([C|Cs]) --> [C], { \+ memberchk(C, `,\r\n`) }, !, plain_field(Cs).
plain_field([]) --> [].

%   rdf_result(+Triples, -Result): a result set in the rs: vocabulary,
%   or a graph.

rdf_result(Ts, Result) :-
    rdf_type(Type),
    rs('ResultSet', RS),
    (   member(rdf(Set, Type, RS), Ts)
    ->  rs_result(Ts, Set, Result)
    ;   findall([s-S, p-P, o-O], ( member(rdf(S0, P0, O0), Ts),
                                   maplist(rdf_term, [S0, P0, O0], [S, P, O])
                                 ), Rows),
        Result = graph(Rows)
    ).

rs_result(Ts, Set, Result) :-
    rs(boolean, BoolP),
    (   member(rdf(Set, BoolP, literal(L)), Ts)
    ->  literal_text(L, B0),
        atom_string(B0, S), atom_string(B, S),
        Result = boolean(B)
    ;   rs(resultVariable, VarP),
        findall(V, ( member(rdf(Set, VarP, literal(L)), Ts), literal_text(L, V) ), Vars),
        rs(solution, SolP), rs(binding, BindP), rs(variable, VP), rs(value, ValP),
        rs(index, IndexP),
        findall(I-Row, ( member(rdf(Set, SolP, Sol), Ts),
                         (   member(rdf(Sol, IndexP, literal(IL)), Ts)
                         ->  literal_text(IL, I0), atom_number(I0, I)
                         ;   I = 0
                         ),
                         findall(N-T, ( member(rdf(Sol, BindP, B), Ts),
                                        member(rdf(B, VP, literal(NL)), Ts),
                                        literal_text(NL, N),
                                        member(rdf(B, ValP, V), Ts),
                                        rdf_term(V, T)
                                      ), Row0),
                         sort(Row0, Row)
                       ), IRows),
        keysort(IRows, Sorted),
        pairs_values(Sorted, Rows),
        Result = table(Vars, Rows)
    ).

		 /*******************************
		 *        ACTUAL RESULTS        *
		 *******************************/

actual(Type, Body, Suite, Result) :-
    sub_atom(Type, 0, _, _, 'application/sparql-results+json'),
    !,
    atom_json_dict(Body, Dict, []),
    json_result(Dict, Result0),
    w3c_iris(Suite, Result0, Result).
actual(Type, Body, Suite, graph(Rows)) :-
    sub_atom(Type, 0, _, _, 'application/n-triples'),
    !,
    setup_call_cleanup(open_string(Body, In),
                       rdf_read_turtle(stream(In), Ts, []),
                       close(In)),
    findall([s-S, p-P, o-O], ( member(rdf(S0, P0, O0), Ts),
                               maplist(rdf_term, [S0, P0, O0], [S1, P1, O1]),
                               maplist(w3c_iri(Suite), [S1, P1, O1], [S, P, O])
                             ), Rows).
actual(Type, Body, Suite, Result) :-
    sub_atom(Type, 0, _, _, 'text/tab-separated-values'),
    !,
    tsv_result(Body, Result0),
    w3c_iris(Suite, Result0, Result).
actual(Type, Body, Suite, csv(Vars, Rows)) :-
    sub_atom(Type, 0, _, _, 'text/csv'),
    csv_rows(Body, [Vars|Rows0]),
    maplist(maplist(w3c_text(Suite)), Rows0, Rows).

w3c_iris(Suite, table(Vs, Rows0), table(Vs, Rows)) :-
    !,
    maplist(w3c_row(Suite), Rows0, Rows).
w3c_iris(Suite, tsv(Vs, Rows0), tsv(Vs, Rows)) :-
    !,
    maplist(w3c_row(Suite), Rows0, Rows).
w3c_iris(Suite, graph(Rows0), graph(Rows)) :-
    !,
    maplist(w3c_row(Suite), Rows0, Rows).
w3c_iris(_, R, R).

w3c_row(Suite, Row0, Row) :-
    maplist(w3c_binding(Suite), Row0, Row).

w3c_binding(Suite, N-T0, N-T) :-
    w3c_iri(Suite, T0, T).

w3c_iri(Suite, iri(I0), iri(I)) :-
    !,
    w3c_text(Suite, I0, I).
w3c_iri(_, T, T).

%   w3c_text(+Suite, +IRI, -W3C): an IRI of the suite's folder as the
%   W3C IRI the expected results use.

w3c_text(Suite, I0, I) :-
    w3c_suite_dir(Dir),
    atomic_list_concat([Dir, Suite], '/', SuiteDir0),
    absolute_file_name(SuiteDir0, SuiteDir),
    uri_file_name(Prefix0, SuiteDir),
    atom_concat(Prefix0, '/', Prefix),
    (   atom(I0), atom_concat(Prefix, Rest, I0)
    ->  suite_base(Suite, Base),
        atom_concat(Base, Rest, I1),
        (   string(I0) -> atom_string(I1, I) ; I = I1 )
    ;   string(I0), atom_string(A0, I0), atom_concat(Prefix, Rest, A0)
    ->  suite_base(Suite, Base),
        atom_concat(Base, Rest, A1),
        atom_string(A1, I)
    ;   I = I0
    ).

		 /*******************************
		 *          COMPARISON          *
		 *******************************/

same_result(boolean(B), boolean(B), _) :- !.
same_result(table(V1, R1), table(V2, R2), Query) :-
    !,
    msort(V1, S), msort(V2, S),
    same_rows(R1, R2, Query).
same_result(tsv(V1, R1), tsv(V2, R2), Query) :-
    !,
    msort(V1, S), msort(V2, S),
    same_rows(R1, R2, Query).
same_result(graph(R1), graph(R2), _) :-
    !,
    sort(R1, S1), sort(R2, S2),
    same_rows(S1, S2, "").
same_result(csv(V, R1), csv(V, R2), Query) :-
    maplist(csv_row(V), R1, T1),
    maplist(csv_row(V), R2, T2),
    same_rows(T1, T2, Query).

csv_row(Vars, Fields, Row) :-
    foldl(csv_binding, Vars, Fields, Row0, []),
    sort(Row0, Row).

csv_binding(V, F, [V-T|R], R) :-
    (   sub_string(F, 0, 2, _, "_:")
    ->  T = bnode(F)
    ;   T = text(F)
    ).

same_rows(R1, R2, Query) :-
    length(R1, N),
    length(R2, N),
    maplist(normal_row, R1, N1),
    maplist(normal_row, R2, N2),
    (   ordered(Query)
    ->  Goal = match_list(N1, N2, [], _)
    ;   Goal = match_bag(N1, N2, [], _)
    ),
    call_with_inference_limit(Goal, 20000000, Result),
    Result \== inference_limit_exceeded,
    !.

ordered(Query) :-
    string_upper(Query, Up),
    sub_string(Up, _, _, _, "ORDER BY").

normal_row(Row0, Row) :-
    maplist(normal_binding, Row0, Row1),
    sort(Row1, Row).

normal_binding(N-T0, N-T) :-
    normal_term(T0, T).

normal_term(lit(Lex, type('http://www.w3.org/2001/XMLSchema#string')), lit(Lex, plain)) :- !.
normal_term(lit(Lex, type(Type)), num(Type, N)) :-
    numeric_type(Type),
    catch(lexical_number(Lex, N), _, fail),
    !.
normal_term(T, T).

%   Numbers of the same datatype compare by value: the lexical form of
%   a computed double or decimal ("1.0E2", "100.0e0") is not fixed.

numeric_type(T) :-
    atom_concat('http://www.w3.org/2001/XMLSchema#', Local, T),
    memberchk(Local, [integer, decimal, double, float]).

lexical_number(Lex, N) :-
    atom_codes(Lex, Codes0),
    exclude(==(0'+), Codes0, Codes1),
    (   Codes1 = [0'.|_]
    ->  Codes2 = [0'0|Codes1]
    ;   append(Pre, [0'-, 0'.|Post], Codes1)
    ->  append(Pre, [0'-, 0'0, 0'.|Post], Codes2)
    ;   Codes2 = Codes1
    ),
    (   append(_, [0'.], Codes2)
    ->  append(Codes2, [0'0], Codes3)
    ;   Codes3 = Codes2
    ),
    number_codes(N0, Codes3),
    N is float(N0).

match_list([], [], M, M).
match_list([R|Rs], [A|As], M0, M) :-
    match_row(R, A, M0, M1),
    match_list(Rs, As, M1, M).

match_bag([], [], M, M).
match_bag([R|Rs], As, M0, M) :-
    select(A, As, As1),
    match_row(R, A, M0, M1),
    match_bag(Rs, As1, M1, M).

match_row([], [], M, M).
match_row([N-T|Ts], [N-U|Us], M0, M) :-
    match_term(T, U, M0, M1),
    match_row(Ts, Us, M1, M).

match_term(bnode(A), bnode(B), M0, M) :-
    !,
    (   memberchk(A-B0, M0)
    ->  B0 == B,
        M = M0
    ;   \+ memberchk(_-B, M0),
        M = [A-B|M0]
    ).
match_term(T, T, M, M).
