:- module(oro_sparql_engine, []).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/oro_knowledge), [oro_find/4]).
:- use_module(library(oro/oro_query), [oro_with_time_limit/1]).
:- use_module(library(oro/sparql/oro_sparql_grammar), [parse_text/3, sparql_error/3, conjunction/2]).
:- use_module(library(oro/sparql/oro_sparql_eval), [run_query/3]).
:- use_module(library(oro/sparql/results/oro_sparql_json), [result_json/2]).
:- use_module(library(oro/sparql/results/oro_sparql_xml), [result_xml/2]).
:- use_module(library(oro/sparql/results/oro_sparql_csv), [result_csv/2]).
:- use_module(library(oro/sparql/results/oro_sparql_tsv), [result_tsv/2]).
:- use_module(library(oro/sparql/results/oro_sparql_turtle), [result_turtle/2]).
:- use_module(library(oro/sparql/results/oro_sparql_ntriples), [result_ntriples/2]).
:- use_module(library(option), [option/3]).

/** <module> SPARQL 1.1 queries over the inference closure of a model

ORO clients send SPARQL: query(key, sparql) and the filters of find
(ORO-SPEC §6.3, §13.3).  This module is oro's SPARQL engine: a parser
of the query language (a tokenizer and a DCG following the productions
of the W3C SPARQL 1.1 grammar) producing a SPARQL algebra term, and an
evaluator of that algebra over oro_holds/4, the inference closure of a
model -- what find and check see.  Its API is the module oro_sparql,
which loads it on first use and calls its entry points (the PUBLIC API
section below) module-qualified.  It exports nothing: the same names
exported from here would clash with oro_sparql's wherever both modules
are imported.

    ?- oro_sparql(myself,
                  "SELECT ?x ?w WHERE { ?x a oro:Monkey ; oro:weight ?w }
                   ORDER BY DESC(?w)", R).
    R = select([x, w], [[x-'http://kb.openrobots.org#gorilla', w-literal(...)], ...]).

Supported: PREFIX and BASE (the server's prefixes are predeclared:
those of oro_prefix/2, and `:` for the default namespace), SELECT
(variables, `*`, DISTINCT, REDUCED, `(Expression AS ?v)`), ASK,
CONSTRUCT (and CONSTRUCT WHERE), DESCRIBE (the triples of each
resource, with those of the blank nodes they reach), FROM, FROM NAMED
and GRAPH (over the graphs of oro_sparql_graph/2), basic
graph patterns with `;`, `,`, blank nodes (`_:b`, `[ ... ]`) and
collections, FILTER, OPTIONAL, UNION, MINUS, BIND, VALUES (inline and
trailing), sub-SELECT, GROUP BY, HAVING, the aggregates COUNT, SUM,
MIN, MAX, AVG, SAMPLE and GROUP_CONCAT, ORDER BY, LIMIT, OFFSET, and
property paths (`/`, `|`, `^`, `*`, `+`, `?`, `!`).  Expressions have
the whole grammar of SPARQL 1.1: `||`, `&&`, comparisons, IN and NOT
IN, arithmetic, EXISTS and NOT EXISTS, and the functions STR, LANG,
LANGMATCHES, DATATYPE, BOUND, IRI, URI, isIRI, isURI, isBLANK,
isLITERAL, isNUMERIC, REGEX, REPLACE, CONTAINS, STRSTARTS, STRENDS,
STRBEFORE, STRAFTER, STRLEN, SUBSTR, UCASE, LCASE, CONCAT,
ENCODE_FOR_URI, STRLANG, STRDT, ABS, CEIL, FLOOR, ROUND, IF, COALESCE,
sameTerm and the XSD casts (xsd:string, xsd:integer, xsd:decimal,
xsd:double, xsd:float, xsd:boolean).  Not supported (a clear parse
error): SERVICE, updates and the date, hash and random functions.

The modules of the engine, one per seam: oro_sparql_lexer (tokens),
oro_sparql_grammar (the DCG, text to algebra: queries and graph
patterns, over oro_sparql_syntax, oro_sparql_triples and
oro_sparql_expressions), oro_sparql_algebra (annotation and the
planner of basic graph patterns), oro_sparql_eval (the evaluator,
datasets, CONSTRUCT and DESCRIBE), oro_sparql_functions (expressions,
functions, aggregates), oro_sparql_terms (term values and their
order, which both of the last two use), and one per result format:
oro_sparql_json, oro_sparql_xml, oro_sparql_csv, oro_sparql_tsv,
oro_sparql_turtle, oro_sparql_ntriples.

Semantics follow the SPARQL 1.1 specification: errors in expressions
make a FILTER false, `||` and `&&` follow the three-valued logic of
§17.2, comparisons follow the operator mapping (numbers by value with
type promotion integer < decimal < float < double, simple literals and
xsd:string as strings, booleans, xsd:dateTime, RDF term equality
otherwise, a type error for literals of incomparable types), FILTER
scope is the group, OPTIONAL filters see both sides, EXISTS substitutes
the current solution.  Two ORO-isms come from the reasoning layer: a
constant literal in a triple pattern matches by value (`12` matches
`"12"^^xsd:int`, strings ignore language tags), and a relative IRI
without BASE is a name in the default namespace (`<fish>` is
oro:fish).  Regular expressions are PCRE (library(pcre)), which covers
the XPath syntax SPARQL uses; the flags `i`, `s`, `m`, `x` and `q` are
supported (without library(pcre), REGEX and REPLACE are expression
errors).  REDUCED keeps every row, as ALL does.  With both ends
unbound, the zero-length matches of `p*` and `p?` are the nodes the
path itself touches, not every node of the model.

Evaluation:

  - A basic graph pattern runs its triple patterns in the order of a
    plan: greedily the pattern expected to have the fewest solutions
    given the variables bound so far, estimated with
    rdf_estimate_complexity/4 on the query's constants, summed over the
    sub-properties of the predicate (or the sub-classes of the class
    for rdf:type), and with rdf_db's branch factors for variables bound
    by earlier patterns.  Patterns whose parts are all bound are checks;
    they run before any pattern that binds a variable, cheapest and
    most selective first.  So a query with several patterns starts from
    its most selective one and does not scan.  A plan is made once per
    query for each set of variables bound on entry.
  - The conjuncts of a FILTER over a basic graph pattern are tested
    inside it, as soon as their variables are bound; operators and
    functions applied to constants are evaluated once.
  - Solutions flow into the next pattern of a join (sideways
    information passing), but only the variables a pattern is certain
    to bind are pushed into it, so FILTER scoping, OPTIONAL and MINUS
    keep their bottom-up meaning.  Without ORDER BY or aggregates,
    solutions stream: LIMIT and ASK stop the evaluation early.
  - A query, its parsing included, is bounded by the setting
    `oro_query:time_limit` (seconds, default 5; 0 for none), as finds
    of several patterns are: past it, evaluation stops with
    `error(resource_error(oro_query_time_limit(Seconds)), _)`.  Queries
    run in the caller's thread (a server worker), so other clients are
    not held up.

Measured (bench/bench_sparql.pl, SWI-Prolog 9.0.4, AMD EPYC, 100k
asserted triples over the common-sense ontology, medians): a join of 3
patterns (23 rows) 4.5 ms, of 4 patterns 7-8 ms, of 5 patterns with an
inferred type and property (213 rows) 11 ms; a find with 4 patterns and
4 filters 34 ms (the 4 patterns alone through oro_find/4: 21 ms);
parsing a 5-pattern query 0.33 ms.  Most of a join is the reasoner's
own work (oro_holds/4 checks, 4 to 8 us each).

Errors are ISO-shaped: a malformed query raises
`error(syntax_error(oro_sparql(Message, Position)), _)` where Message
is one line naming the line and column and Position is the 0-based
character offset in the query text.
*/

		 /*******************************
		 *           PUBLIC API         *
		 *******************************/

%!  oro_sparql_parse(+Text, -Query) is det.
%
%   Called by oro_sparql:oro_sparql_parse/2, which documents it.

oro_sparql_parse(Text, Query) :-
    must_be(text, Text),
    parse_text(query, Text, Query).

%!  oro_sparql(+Model, +Text, -Result) is det.
%
%   Called by oro_sparql:oro_sparql/3, which documents it.

oro_sparql(Model0, Text, Result) :-
    oro_resolve_model(Model0, Model),
    oro_with_time_limit(( oro_sparql_parse(Text, Query0),
                          query_dataset(Query0, Model, true, [], [], Query, DS),
                          run_query(DS, Query, Result)
                        )).

%!  oro_sparql(+Model, +Text, -Result, +Options) is det.
%
%   Called by oro_sparql:oro_sparql/4, which documents it.

oro_sparql(Model0, Text, Result, Options) :-
    oro_resolve_model(Model0, Model),
    must_be(list, Options),
    option(infer(Infer), Options, true),
    must_be(boolean, Infer),
    findall(G, member(default_graph(G), Options), Defaults),
    findall(G, member(named_graph(G), Options), Named),
    maplist(must_be(atom), Defaults),
    maplist(must_be(atom), Named),
    oro_with_time_limit(( oro_sparql_parse(Text, Query0),
                          query_dataset(Query0, Model, Infer, Defaults, Named,
                                        Query, DS),
                          run_query(DS, Query, Result)
                        )).

%   query_dataset(+Query0, +Model, +Infer, +Defaults, +Named, -Query,
%   -Dataset): the dataset of a query (see run_query/3).  Graphs given
%   by the caller (the protocol's default-graph-uri and
%   named-graph-uri) override those of the query's FROM and FROM NAMED.
%   Without either, the default graph is Model (its inference closure,
%   or its asserted triples if Infer is false) and every graph of the
%   store is a named graph; with either, the dataset is exactly the
%   graphs named (an empty default graph if none).

query_dataset(Query0, Model, Infer, Defaults0, Named0, Query, Dataset) :-
    (   Query0 = from(FromDefaults, FromNamed, Query)
    ->  true
    ;   Query = Query0,
        FromDefaults = [],
        FromNamed = []
    ),
    (   ( Defaults0 \== [] ; Named0 \== [] )
    ->  Defaults = Defaults0,
        Named = Named0
    ;   Defaults = FromDefaults,
        Named = FromNamed
    ),
    (   Defaults == [],
        Named == []
    ->  (   Infer == true
        ->  Default = Model
        ;   Default = asserted(Model)
        ),
        findall(IRI-[G], oro_sparql_graph(IRI, G), NamedGraphs)
    ;   maplist(iri_graphs, Defaults, Graphss),
        append(Graphss, Graphs0),
        sort(Graphs0, Graphs),
        Default = graphs(Graphs),
        sort(Named, NamedIRIs),
        findall(IRI-Gs, ( member(IRI, NamedIRIs),
                          iri_graphs(IRI, Gs)
                        ), NamedGraphs)
    ),
    Dataset = ds(Default, NamedGraphs).

iri_graphs(IRI, Graphs) :-
    findall(G, oro_sparql_graph(IRI, G), Graphs).

%!  oro_sparql_graph(?IRI, ?Graph) is nondet.
%
%   Called by oro_sparql:oro_sparql_graph/2, which documents it.

oro_sparql_graph(IRI, Graph) :-
    (   oro_graph_layer(Graph, _, profile(_)),
        IRI = Graph
    ;   oro_ontology_graph(Graph),
        rdf_graph_property(Graph, source(IRI))
    ).

%!  oro_sparql_result_text(+Format, +Result, -Text) is det.
%
%   Called by oro_sparql:oro_sparql_result_text/3, which documents it.

oro_sparql_result_text(json, Result, Text) :-
    result_json(Result, Text).
oro_sparql_result_text(xml, Result, Text) :-
    result_xml(Result, Text).
oro_sparql_result_text(csv, Result, Text) :-
    result_csv(Result, Text).
oro_sparql_result_text(tsv, Result, Text) :-
    result_tsv(Result, Text).
oro_sparql_result_text(turtle, Result, Text) :-
    result_turtle(Result, Text).
oro_sparql_result_text(ntriples, Result, Text) :-
    result_ntriples(Result, Text).

%!  oro_sparql_json(+Model, +Text, -JSON) is det.
%
%   Called by oro_sparql:oro_sparql_json/3, which documents it.

oro_sparql_json(Model, Text, JSON) :-
    oro_sparql(Model, Text, Result),
    (   Result = graph(_)
    ->  sparql_error("a SELECT or ASK query is expected", 0, Text)
    ;   result_json(Result, JSON)
    ).

%!  oro_query_values(+Model, +Key, +Text, -Values) is det.
%
%   Called by oro_sparql:oro_query_values/4, which documents it.

oro_query_values(Model0, Key, Text, Values) :-
    oro_resolve_model(Model0, Model),
    must_be(text, Key),
    key_name(Key, Name),
    oro_with_time_limit(( oro_sparql_parse(Text, Query0),
                          query_dataset(Query0, Model, true, [], [], Query, DS),
                          (   Query = select(_, _, _, _)
                          ->  true
                          ;   sparql_error("a SELECT query is expected", 0, Text)
                          ),
                          run_query(DS, Query, select(_, Rows))
                        )),
    findall(V, ( member(Row, Rows),
                 memberchk(Name-V, Row),
                 \+ rdf_is_bnode(V)
               ), Vs),
    sort(Vs, Values).

key_name(Key, Name) :-
    atom_string(Atom, Key),
    normalize_space(atom(Trimmed), Atom),
    (   ( sub_atom(Trimmed, 0, 1, _, ?) ; sub_atom(Trimmed, 0, 1, _, $) )
    ->  sub_atom(Trimmed, 1, _, 0, Name)
    ;   Name = Trimmed
    ).

%!  oro_find(+Model, +Var, +Patterns, +Filters, -Values) is det.
%
%   Called by oro_sparql:oro_find/5, which documents it.

oro_find(Model0, Var, Patterns, Filters, Values) :-
    oro_resolve_model(Model0, Model),
    must_be(list, Patterns),
    must_be(list(text), Filters),
    (   Filters == []
    ->  oro_find(Model, Var, Patterns, Values)
    ;   Patterns == []
    ->  (   text(Var)
        ->  find_variable_name(Var, _)
        ;   true
        ),
        Values = []
    ;   copy_term(Var-Patterns, Var1-Patterns1),
        oro_statements(Patterns1, Triples, Bindings),
        (   text(Var1)
        ->  find_variable_name(Var1, Name)
        ;   must_be(var, Var1),
            Name = '_:find',
            Var1 = var(Name)
        ),
        maplist(bind_name, Bindings),
        term_variables(Triples, Anonymous),
        foldl(name_anonymous, Anonymous, 1, _),
        Pattern = filter(Filter, bgp(Triples)),
        Query = select([var(Name)], all, Pattern,
                       mods(false, none, [], [], 0, inf, none)),
        oro_with_time_limit(( maplist(parse_filter, Filters, Exprs),
                              conjunction(Exprs, Filter),
                              run_query(ds(Model, []), Query, select(_, Rows))
                            )),
        findall(V, ( member(Row, Rows),
                     memberchk(Name-V, Row),
                     \+ rdf_is_bnode(V)
                   ), Vs),
        sort(Vs, Values)
    ).

text(X) :-
    (   string(X)
    ->  true
    ;   atom(X)
    ).

find_variable_name(Text, Name) :-
    key_name(Text, Name),
    (   Name == ''
    ->  domain_error(oro_variable, Text)
    ;   true
    ).

bind_name(Name=var(Name)).

name_anonymous(var(Name), N0, N) :-
    format(atom(Name), '_:a~d', [N0]),
    N is N0 + 1.

parse_filter(Text, Expr) :-
    parse_text(expression, Text, Expr).

		 /*******************************
		 *           MESSAGES           *
		 *******************************/

:- multifile prolog:error_message//1.

prolog:error_message(syntax_error(oro_sparql(Message, _Position))) -->
    [ 'SPARQL: ~w'-[Message] ].

