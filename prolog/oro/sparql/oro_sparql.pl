:- module(oro_sparql,
          [ oro_sparql_parse/2,         % +Text, -Query
            oro_sparql/3,               % +Model, +Text, -Result
            oro_sparql/4,               % +Model, +Text, -Result, +Options
            oro_sparql_graph/2,         % ?IRI, ?Graph
            oro_sparql_result_text/3,   % +Format, +Result, -Text
            oro_sparql_json/3,          % +Model, +Text, -JSON
            oro_query_values/4,         % +Model, +Key, +Text, -Values
            oro_find/5,                 % +Model, +Var, +Patterns, +Filters, -Values
            oro_sparql_load/0
          ]).
:- use_module(library(filesex), [directory_file_path/3]).
:- use_module(library(oro/oro_knowledge), [oro_find/4]).

/** <module> SPARQL 1.1 queries over the inference closure of a model

The SPARQL API of oro (ORO-SPEC §6.3, §13.3): the predicates below,
re-exported by library(oro).  The engine that runs them, the module
`oro_sparql_engine` (prolog/oro/sparql/oro_sparql_engine.pl, whose
documentation says what it supports and how it evaluates), is loaded
by the first call of one of them, not with this module: it is a fifth
of oro's code and, with the regular expressions and dates its filters
need, about a sixth of the time a server takes to load its code.  A
robot that never sends a query does not wait for it; oro_sparql_load/0
loads it ahead, as the server does once it listens.
*/

%!  oro_sparql_load is det.
%
%   Load the SPARQL engine if it is not loaded yet.  The predicates of
%   this module call it first; call it ahead to spare the first query
%   the load (50-80 ms on a 2-core VM).  Safe in any thread: a thread
%   calling it while another loads the engine waits for that load to
%   end.

oro_sparql_load :-
    (   engine_loaded
    ->  true
    ;   module_property(oro_sparql, file(File)),
        file_directory_name(File, Dir),
        directory_file_path(Dir, oro_sparql_engine, Engine),
        use_module(Engine, []),
        (   engine_loaded
        ->  true
        ;   assertz(engine_loaded)
        )
    ).

%   engine_loaded: the engine's load has ended (set once, never
%   cleared).  It spares a query the 30-50 us of use_module/2 finding
%   the file loaded; before, a thread that sees it absent calls
%   use_module/2, which waits for a load in progress.

:- dynamic engine_loaded/0.

%!  oro_sparql_parse(+Text, -Query) is det.
%
%   Parse the SPARQL query Text (an atom or string) into Query, a SPARQL
%   algebra term:
%
%     - select(Projection, Distinct, Pattern, Modifiers), Projection a
%       list of var(Name) and as(Expression, Name), Distinct one of
%       `all`, `distinct` or `reduced`;
%     - ask(Pattern, Modifiers).
%
%   Pattern is built from bgp(Triples), join/2, left_join/3, union/2,
%   minus/2, filter/2, extend/3, values/2 and subselect/1; variables
%   are var(Name), Name an atom without `?`; IRIs and literals are
%   rdf_db terms.
%
%   @error syntax_error(oro_sparql(Message, Position)) if Text is not a
%          query this engine understands.

oro_sparql_parse(Text, Query) :-
    oro_sparql_load,
    oro_sparql_engine:oro_sparql_parse(Text, Query).

%!  oro_sparql(+Model, +Text, -Result) is det.
%
%   Run the SPARQL query Text over the inference closure of Model.
%   Result is select(Vars, Rows) for a SELECT query, Vars the projected
%   variable names (atoms) and Rows a list of rows, each a list of
%   Var-Value pairs in the order of Vars, for the variables bound in
%   that row (Value an IRI, a blank node or an rdf_db literal term);
%   ask(Bool) for an ASK query; graph(Triples), a sorted list of
%   rdf(S, P, O), for CONSTRUCT and DESCRIBE.  FROM, FROM NAMED and
%   GRAPH name the graphs of oro_sparql_graph/2; without FROM, every
%   graph of the store is a named graph.
%
%   @error existence_error(agent, Model) for an unknown model.
%   @error syntax_error(oro_sparql(Message, Position)) for a malformed
%          query.
%   @error resource_error(oro_query_time_limit(Seconds)) if the query
%          runs longer than the `time_limit` setting.

oro_sparql(Model, Text, Result) :-
    oro_sparql_load,
    oro_sparql_engine:oro_sparql(Model, Text, Result).

%!  oro_sparql(+Model, +Text, -Result, +Options) is det.
%
%   As oro_sparql/3, over the dataset Options describe:
%
%     - infer(Bool): with `true` (the default) the default graph is the
%       inference closure of Model; with `false` it is the triples
%       asserted in Model (its memory profiles and the ontologies it
%       did not remove triples from), without inference.
%     - default_graph(IRI), repeatable: the default graph is the RDF
%       merge of these graphs (see oro_sparql_graph/2), as they are
%       stored (infer/1 does not apply); a graph IRI naming no graph
%       of the store is an empty graph.
%     - named_graph(IRI), repeatable: the named graphs GRAPH sees.
%
%   With default_graph/1 or named_graph/1, the dataset is exactly the
%   graphs they name, and the query's FROM and FROM NAMED are ignored
%   (as the SPARQL 1.1 Protocol says).
%
%   @error existence_error(agent, Model) for an unknown model.
%   @error syntax_error(oro_sparql(Message, Position)) for a malformed
%          query.
%   @error resource_error(oro_query_time_limit(Seconds)) if the query
%          runs longer than the `time_limit` setting.

oro_sparql(Model, Text, Result, Options) :-
    oro_sparql_load,
    oro_sparql_engine:oro_sparql(Model, Text, Result, Options).

%!  oro_sparql_graph(?IRI, ?Graph) is nondet.
%
%   Graph is the rdf_db graph a SPARQL dataset names IRI: each memory
%   profile of each model is a graph named as in rdf_db
%   (`oro:myself#longterm`, see oro_graph/3), and each ontology file
%   loaded is the graph named by the URL it was loaded from (its
%   `file://` URL).

oro_sparql_graph(IRI, Graph) :-
    oro_sparql_load,
    oro_sparql_engine:oro_sparql_graph(IRI, Graph).

%!  oro_sparql_result_text(+Format, +Result, -Text) is det.
%
%   Text (a string) is Result, as oro_sparql/3 gives it, in Format.
%   For select/2 and ask/1: `json` (SPARQL 1.1 Query Results JSON),
%   `xml` (SPARQL Query Results XML), `csv` or `tsv` (SPARQL 1.1 Query
%   Results CSV and TSV).  For graph/1: `turtle` or `ntriples`.
%
%   @error domain_error(sparql_result_format(Kind), Format) if Format
%          does not write Result (Kind `bindings` or `graph`).

oro_sparql_result_text(Format, Result, Text) :-
    must_be(oneof([json, xml, csv, tsv, turtle, ntriples]), Format),
    (   Result = graph(_)
    ->  Kind = graph,
        Formats = [turtle, ntriples]
    ;   Kind = bindings,
        Formats = [json, xml, csv, tsv]
    ),
    (   memberchk(Format, Formats)
    ->  true
    ;   domain_error(sparql_result_format(Kind), Format)
    ),
    oro_sparql_load,
    oro_sparql_engine:oro_sparql_result_text(Format, Result, Text).

%!  oro_sparql_json(+Model, +Text, -JSON) is det.
%
%   As oro_sparql/3, with the result as a string in the SPARQL 1.1
%   Query Results JSON Format, on one line.
%
%   @error syntax_error(oro_sparql(Message, 0)) for a CONSTRUCT or
%          DESCRIBE query, whose result is a graph.

oro_sparql_json(Model, Text, JSON) :-
    oro_sparql_load,
    oro_sparql_engine:oro_sparql_json(Model, Text, JSON).

%!  oro_query_values(+Model, +Key, +Text, -Values) is det.
%
%   Values is the ordered set of the values of the variable Key (`x`
%   or `?x`) over the results of the SELECT query Text, as ORO's
%   query(key, sparql) answers them: rows where Key is unbound and
%   blank nodes are left out; literals are kept.  A Key the query does
%   not project gives `[]`.
%
%   @error syntax_error(oro_sparql(Message, Position)) also for an ASK
%          query.

oro_query_values(Model, Key, Text, Values) :-
    oro_sparql_load,
    oro_sparql_engine:oro_query_values(Model, Key, Text, Values).

%!  oro_find(+Model, +Var, +Patterns, +Filters, -Values) is det.
%
%   As oro_find/4 (ORO statement patterns, sharing their variables),
%   keeping only the solutions where every SPARQL expression of Filters
%   (texts such as `"?w >= 48"` or `"regex(?l, 'king')"`, ANDed) is
%   true.  Names in filters are not expanded: write `oro:x`, `:x` or a
%   full IRI.  Var is a variable name (`o` or `?o`), or, with term
%   patterns, a Prolog variable of Patterns.  As in ORO, no pattern
%   gives `[]` whatever the filters.  Without filters it is oro_find/4,
%   and does not load the engine.
%
%   @error domain_error(oro_variable, '') for an empty variable name.
%   @error syntax_error(oro_sparql(Message, Position)) for a malformed
%          filter (Position is in that filter's text).
%   @error resource_error(oro_query_time_limit(Seconds)) as oro_sparql/3.

oro_find(Model, Var, Patterns, Filters, Values) :-
    (   Filters == []
    ->  oro_find(Model, Var, Patterns, Values)
    ;   oro_sparql_load,
        oro_sparql_engine:oro_find(Model, Var, Patterns, Filters, Values)
    ).
